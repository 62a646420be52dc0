// A particle's particle-shifting sums over its later neighbours in cell order, each pair once:
// the moment matrix and concentration gradient of FreeSurfaceMarrone2010.hpp, the law's sum
// (TensileShiftingWeight.hpp) and the density differences of the renormalised density gradient.
// What k receives is summed in registers and added once; what each neighbour receives is added
// to its place. A pair's terms are the same for both particles but for the other's volume and the
// gradient's sign. The shifting pass (ParticleShiftingPass.tpp) calls it on the lists it makes;
// the force loop (FluidRates.tpp), where an evaluation is asked for the sums, on the lists it has,
// without the moment and density differences where delta-SPH's gradient pass summed them.
#pragma once

#include "neighbourSearch/CellLinkedList.hpp"
#include "particleShifting/TensileShiftingWeight.hpp"
#include "physics/ParticleShiftingScratch.hpp"

#include <array>
#include <cstdint>
#include <type_traits>

namespace sph {

// The 2D force loop hands over each listed pair's distance and kernel gradient factor, which it
// evaluated already (Given: their latency was most of the sums' cost); the shifting pass and the
// force loop in lanes (3D) evaluate them here. Flattened: called from two loops, GCC left
// Eigen's 3D products out of line, one call per pair and term (the 3D benchmark's sums took
// twice the time).
struct PairGeometry {
    const double* distance;
    const double* gradientFactor;
};

template <bool Wraps, bool WithMoment, bool Given, int D, class Kernel, class Weight>
[[gnu::flatten]] void addShiftingPairsWeighted(const CellLinkedList<D>& cells, const Kernel& kernel, const ParticleShiftingScratch<D>& scratch,
                                               std::size_t k, const std::array<double, std::size_t{D}>& xk, const std::uint32_t* listed,
                                               std::size_t count, [[maybe_unused]] PairGeometry given,
                                               typename ParticleShiftingScratch<D>::Sums* sums, [[maybe_unused]] Weight weight) {
    using Matrix = Eigen::Matrix<double, D, D>;
    constexpr bool sumsLaw = !std::is_same_v<Weight, UnitShiftingWeight>;
    const double* const volume = scratch.volume.data();
    const double* const density = scratch.density.data();
    const double* const xs = cells.sortedPosition(0).data();
    [[maybe_unused]] const double inverseWdx = scratch.inverseWdx;
    const double volumeK = volume[k], densityK = density[k];
    Matrix momentK = Matrix::Zero();
    Vec<D> gradientK = Vec<D>::Zero(), lawK = Vec<D>::Zero(), differencesK = Vec<D>::Zero();
    for (std::size_t q = 0; q < count; ++q) {
        const std::size_t l = listed[q];
        Vec<D> r;
        for (int d = 0; d < D; ++d) r[d] = cells.template separation<Wraps>(xk[d] - xs[l * D + d], d);
        const Vec<D> Fr = (Given ? given.gradientFactor[q] : kernel.gradientFactor(r.norm())) * r;
        gradientK += volume[l] * Fr;
        auto& atL = sums[l];
        atL.gradient -= volumeK * Fr;
        if constexpr (sumsLaw) {
            const double distance = Given ? given.distance[q] : r.norm();
            const Vec<D> weightFr = weight(kernel.value(distance) * inverseWdx) * Fr;
            lawK += volume[l] * weightFr;
            atL.law -= volumeK * weightFr;
        }
        if constexpr (WithMoment) {
            const Vec<D> differenceFr = (density[l] - densityK) * Fr;
            momentK.noalias() -= (volume[l] * Fr) * r.transpose();
            differencesK += volume[l] * differenceFr;
            atL.moment.noalias() -= (volumeK * Fr) * r.transpose();
            atL.densityDifferences += volumeK * differenceFr;
        }
    }
    auto& atK = sums[k];
    atK.gradient += gradientK;
    atK.law += lawK;
    if constexpr (WithMoment) {
        atK.moment += momentK;
        atK.densityDifferences += differencesK;
    }
}

// The same with the scratch's weight as its own type (a branch per particle).
template <bool Wraps, bool WithMoment, bool Given, int D, class Kernel>
void addShiftingPairs(const CellLinkedList<D>& cells, const Kernel& kernel, const ParticleShiftingScratch<D>& scratch, std::size_t k,
                      const std::array<double, std::size_t{D}>& xk, const std::uint32_t* listed, std::size_t count, PairGeometry given,
                      typename ParticleShiftingScratch<D>::Sums* sums) {
    withShiftingWeight(scratch.weight, [&](auto weight) {
        addShiftingPairsWeighted<Wraps, WithMoment, Given>(cells, kernel, scratch, k, xk, listed, count, given, sums, weight);
    });
}

}  // namespace sph
