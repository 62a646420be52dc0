// Fluid regions of system/generateParticlesDict, filled with particles on a square lattice of
// spacing dx (cell-centred: the first particle is dx/2 inside the region's edge).
//   fluid
//   {
//       column { type box; min (0 0); max (0.4 0.8); velocity (0 0); }   // 1D, 2D, 3D
//       vortex { type box; min (0 0); max (1 1); velocity { type taylorGreen; U 1; L 1; nu 0.01; } }
//       drop   { type ellipse; centre (0 0); semiAxes (1 1); }          // 2D (circle: radius 1;)
//       wedge  { type polygon; points ((0 0) (1 0) (0 1)); }           // 2D
//   }
// A box's extent must be a whole number of spacings; other shapes keep the lattice points
// (anchored at the domain's min corner) that fall inside them.
#pragma once

#include "analytic/AnalyticSolution.hpp"
#include "core/Vector.hpp"
#include "io/Dictionary.hpp"

#include <memory>
#include <vector>

namespace sph {

template <int D>
struct FluidRegionParticles {
    std::vector<Vec<D>> positions;
    Vec<D> velocity = Vec<D>::Zero();                          // a constant velocity, or
    std::shared_ptr<const AnalyticSolution<D>> initialField;  // the velocity (and pressure) of a solution at t = 0
};

template <int D>
FluidRegionParticles<D> fillFluidRegion(const Dictionary& region, double dx, const Vec<D>& domainMin, const Vec<D>& domainMax);

// What a particle costs the solver (its fields, the integrator's stages, its share of the
// neighbour search): an estimate, high rather than low, to refuse a runaway size before allocating.
constexpr double solverBytesPerParticle = 1024.0;
// Lattice indices are ints: no extent may span more spacings.
constexpr int maxSpacingsAcross = 2147483647;

// Number of whole spacings in [lo, hi]; FatalError naming the keyword when it is not whole.
int wholeSpacings(const Dictionary& dict, const std::string& keyword, double lo, double hi, double dx);

}  // namespace sph
