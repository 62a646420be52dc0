// forces: the force the fluid exerts on wall patches, over time. For wall-particle patches
// (dummyParticles, dynamicBoundary) it is the reaction of the fluid-wall pair terms of the
// momentum equation, summed over the patch's particles w and their fluid neighbours i:
//   F = -sum_w sum_i m_i m_w [ -(p_i/rho_i^2 + p_w/rho_w^2) grad W_iw + viscous term ]
// (physics/FluidWallPair.hpp: the very terms of the fluid's acceleration), at the present
// state. For a wall-force patch (deficiency correction, repulsion) it is the reaction of the
// accelerations its wall forces gave the fluid, F = -sum_i m_i a_i^patch, as the system
// recorded it at the last evaluation of the rates (Patch::load; the step's end state with
// verlet, symplectic and predictorCorrector, the last stage's with the others), as a free
// body's loads are taken. Writes postProcessing/<name>/<t0>/forces.dat: time, then the force
// components of each patch. In still water the patches of a tank carry the water's weight. An
// unknown patch is an error before the first step; a free body's loads are reported by
// bodyMotion.
// Example (system/controlDict, functions):
//   wallLoads { type forces; patches (tank); executeInterval 0.01; }
#pragma once

#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <vector>

namespace sph {

template <int D>
class PatchForces : public FunctionObject<D> {
public:
    PatchForces(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;

    std::vector<Vec<D>> forces(const FluidSystemView<D>& system) const;  // one per patch (exposed for tests)

private:
    const Reductions& reductions_;  // over the processes that share the particles
    std::vector<std::string> names_;
    std::vector<std::size_t> patches_;  // indices into the system's patches
    TimeSeriesFile out_;
};

}  // namespace sph
