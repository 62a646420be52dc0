#include "functionObjects/PatchForces.hpp"

#include "functionObjects/PatchByName.hpp"

#include "physics/FluidSystemView.hpp"
#include "physics/FluidWallPair.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace sph {

template <int D>
PatchForces<D>::PatchForces(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions), names_(dict.get<std::vector<std::string>>("patches")) {
    if (names_.empty()) dict.fail("patches", "lists no patch");
    const auto& patches = context.system.patches;
    std::string header = "# time";
    for (const std::string& name : names_) {
        const auto k = static_cast<std::size_t>(&patchByName(dict, "patches", name, context.system) - patches.data());
        if (!patches[k].model->actsThroughWallParticles()) {
            if (!context.recordPatchLoad) throw std::logic_error("forces on a wall-force patch needs a system that records its load");
            context.recordPatchLoad(k);
        }
        patches_.push_back(k);
        for (int d = 0; d < D; ++d) header += fmt::format(" {}_F{}", name, "xyz"[d]);
    }
    out_ = context.series("forces.dat", header);
}

template <int D>
std::string PatchForces<D>::describe() const {
    return fmt::format("forces on {}", fmt::join(names_, ", "));
}

template <int D>
std::vector<Vec<D>> PatchForces<D>::forces(const FluidSystemView<D>& system) const {
    const auto& v = system.fluid[fields::velocity];
    const auto& m = system.fluid[fields::mass];
    const auto& rho = system.fluid[fields::density];
    const auto& p = system.fluid[fields::pressure];
    const auto& walls = system.walls;
    const WallPairFields<D> wall{walls[fields::mass].data(), walls[fields::pressure].data(), walls[fields::density].data(),
                                 system.viscous ? walls[fields::viscousVelocity].data() : nullptr};
    const double eta2 = viscousRegularisation(system.smoothingLength);
    // Each wall particle's load from its fluid neighbours, then their exact sum per patch.
    std::vector<ExactSum> totals(patches_.size() * D);
    std::visit(
        [&](const auto& kernel, const auto& viscosity) {
            for (std::size_t k = 0; k < patches_.size(); ++k) {
                const Patch<D>& patch = system.patches[patches_[k]];
                if (!patch.model->actsThroughWallParticles()) {  // recorded by the last evaluation
                    for (int d = 0; d < D; ++d) totals[k * D + static_cast<std::size_t>(d)] = patch.load[static_cast<std::size_t>(d)];
                    continue;
                }
                for (std::size_t w = patch.begin; w < patch.end; ++w) {
                    if (!system.ownsWall(w)) continue;
                    Vec<D> force = Vec<D>::Zero();
                    system.fluidCells.forEachNeighbour(
                        walls.position[w], system.supportRadius, [&](std::uint32_t i, const Vec<D>& fromFluid, double r2) {
                            const Vec<D> r = -fromFluid;  // x_i - x_w, as the fluid's loop has it
                            const double F = kernel.gradientFactor(std::sqrt(r2));
                            force -= m[i] * fluidWallAcceleration<true>(viscosity, r, r2, F, eta2, p[i] / (rho[i] * rho[i]), rho[i], v[i], wall, w);
                        });
                    for (int d = 0; d < D; ++d) totals[k * D + static_cast<std::size_t>(d)].add(force[d]);
                }
            }
        },
        system.kernel, system.viscosity);
    reductions_.sum(totals);
    std::vector<Vec<D>> result(patches_.size());
    for (std::size_t k = 0; k < patches_.size(); ++k)
        for (int d = 0; d < D; ++d) result[k][d] = totals[k * D + static_cast<std::size_t>(d)].value();
    return result;
}

template <int D>
void PatchForces<D>::execute(const FluidSystemView<D>& system, double t) {
    std::string line = fmt::format("{:.9g}", t);
    for (const Vec<D>& force : forces(system)) line += fmt::format(" {:.9g}", fmt::join(force, " "));
    out_.append(line);
}

template class PatchForces<1>;
template class PatchForces<2>;
template class PatchForces<3>;

}  // namespace sph
