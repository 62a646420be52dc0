// Stops a run that has blown up, with the step, time, particle and quantity. A fluid particle has
// blown up when its position or velocity is not finite, it moves faster than the speed of sound
// c0 (weakly compressible flow is meaningless past Mach 1), its density leaves [0.5, 2] rho0, or
// it leaves the domain. Checked after every step: the pass over all particles runs in parallel,
// and the report names the first faulty particle in storage order, whatever the thread count.
#pragma once

#include "core/ParticleSet.hpp"

namespace sph {

struct FluidStateLimits {
    double c0;    // speed of sound [m/s]
    double rho0;  // reference density [kg/m^3]
};

// Throws FatalError naming the first faulty particle of `fluid` (owned ones only).
template <int D>
void checkFluidState(const ParticleSet<D>& fluid, const Vec<D>& domainMin, const Vec<D>& domainMax, FluidStateLimits limits, long step, double t);

}  // namespace sph
