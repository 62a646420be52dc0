#include "functionObjects/FirstParticleSpacing.hpp"

#include "io/ParticleState.hpp"

#include <array>
#include <cmath>
#include <tuple>

namespace sph {

template <int D>
std::optional<double> firstParticleSpacing(const FluidSystemView<D>& system, const Reductions& reductions) {
    const ParticleSet<D>& fluid = system.fluid;
    const int* cell = fluid.optionalData(fields::orderCell);
    const int* rank = fluid.optionalData(fields::orderRank);
    // This process's candidate: whether it has one, its place in the serial order, its spacing.
    std::array<double, 4> mine{0.0, 0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < fluid.ownedCount(); ++i) {
        if (!system.ownsFluid(i)) continue;
        const std::array<double, 4> candidate{1.0, cell ? cell[i] : 0.0, rank ? rank[i] : 0.0,
                                              std::pow(fluid[fields::mass][i] / fluid[fields::density][i], 1.0 / D)};
        if (mine[0] == 0.0 || std::tie(candidate[1], candidate[2]) < std::tie(mine[1], mine[2])) mine = candidate;
        if (!cell) break;  // the serial run's: its first particle
    }
    const std::vector<double> all = reductions.gather(mine);
    std::optional<std::array<double, 4>> first;
    for (std::size_t at = 0; at + 4 <= all.size(); at += 4) {
        const std::array<double, 4> candidate{all[at], all[at + 1], all[at + 2], all[at + 3]};
        if (candidate[0] != 0.0 && (!first || std::tie(candidate[1], candidate[2]) < std::tie((*first)[1], (*first)[2]))) first = candidate;
    }
    return first ? std::optional<double>((*first)[3]) : std::nullopt;
}

template std::optional<double> firstParticleSpacing<1>(const FluidSystemView<1>&, const Reductions&);
template std::optional<double> firstParticleSpacing<2>(const FluidSystemView<2>&, const Reductions&);
template std::optional<double> firstParticleSpacing<3>(const FluidSystemView<3>&, const Reductions&);

}  // namespace sph
