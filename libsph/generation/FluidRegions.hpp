// Fluid regions of system/generateParticlesDict, filled with particles on a square lattice of
// spacing dx (cell-centred: the first particle is dx/2 inside the region's edge).
//   fluid
//   {
//       column { type box; min (0 0); max (0.4 0.8); velocity (0 0); }   // 1D, 2D, 3D
//       vortex { type box; min (0 0); max (1 1); velocity { type taylorGreen; U 1; L 1; nu 0.01; } }
//       drop   { type ellipse; centre (0 0); semiAxes (1 1); }          // 2D (circle: radius 1;)
//       wedge  { type polygon; points ((0 0) (1 0) (0 1)); }           // 2D
//   }
// A box spans the whole number of spacings nearest its extent along each axis, its lattice
// anchored at min; where the extent is not a whole number of spacings, the last particle sits
// dx/2 inside max and the last spacing takes the difference (between dx/2 and 3 dx/2; a note
// says so). Other shapes keep the lattice points (anchored at the domain's min corner) that
// fall inside them.
#pragma once

#include "analytic/AnalyticSolution.hpp"
#include "core/Registry.hpp"
#include "core/Vector.hpp"
#include "io/Dictionary.hpp"

#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sph {

template <int D>
struct FluidRegionParticles {
    std::vector<Vec<D>> positions;
    Vec<D> velocity = Vec<D>::Zero();                         // a constant velocity, or
    std::shared_ptr<const AnalyticSolution<D>> initialField;  // the velocity (and pressure) of a solution at t = 0
    std::vector<std::string> notes;                           // adjusted spacings, for the user to read
};

// The rows of a lattice's last axis (y in 2D, z in 3D: the slowest in the filling order) that
// one of `count` generators fills (generateParticles -parallel); one fills them all.
struct LatticeShare {
    int rank = 0, count = 1;
    // This share's rows of [first, last]: consecutive, the shares in rank order (empty where
    // the first returned exceeds the last).
    std::pair<long, long> rows(long first, long last) const;
};

// What a shape is generated within: the domain (its lattice is anchored at min), the case
// directory, which file names are relative to, and the share of the lattice to fill.
template <int D>
struct GenerationDomain {
    Vec<D> min, max;
    std::filesystem::path caseDirectory;
    LatticeShare share = {};
};

// A shape declared for other dimensions than the case's (`what`: "fluid region", "wall patch"),
// reported at its `type` word.
[[noreturn]] void shapeForOtherDimensions(const Dictionary& dict, const std::string& what, const std::string& dimensions, int D);

// The fluid region shapes, selected by `type` (each declared once, with its keywords, for the
// generator and -listModels); a shape fills the lattice points it holds and may add notes.
template <int D>
using FluidShapeRegistry = Registry<std::vector<Vec<D>>, const Dictionary&, double, const GenerationDomain<D>&, std::vector<std::string>&>;
template <int D>
FluidShapeRegistry<D> makeFluidShapeRegistry();

template <int D>
FluidRegionParticles<D> fillFluidRegion(const Dictionary& region, double dx, const GenerationDomain<D>& domain);

// What a particle costs the solver (its fields, the integrator's stages, its share of the
// neighbour search): an estimate, high rather than low, to refuse a runaway size before allocating.
constexpr double solverBytesPerParticle = 1024.0;
// Lattice indices are ints: no extent may span more spacings.
constexpr int maxSpacingsAcross = 2147483647;

// The lattice along one axis of a box [lo, hi]: `count` points, the whole number of spacings
// nearest (hi - lo) / dx, at lo + (i + 1/2) dx; when the extent is not whole, the last sits
// dx/2 inside hi (at the middle when it is the only one), and points beyond the box (walls'
// layers, i < 0 or i >= count) continue the lattice outwards from the nearer end.
struct LatticeAxis {
    double lo, hi, dx;
    int count;
    bool whole;  // the extent is a whole number of spacings (to 1e-6): the plain lattice

    double operator()(int i) const {
        if (whole || i < count - 1) return lo + (i + 0.5) * dx;
        if (i == count - 1) return count == 1 ? 0.5 * (lo + hi) : hi - 0.5 * dx;
        return hi + (i - count + 0.5) * dx;
    }
    // The length of the box along this axis that point i (0 <= i < count) stands for.
    double extent(int i) const {
        if (whole) return dx;
        if (count == 1) return hi - lo;
        return i >= count - 2 ? 0.5 * (dx + (hi - lo) - (count - 1) * dx) : dx;
    }
    // "the x extent 0.41 is 20.5 dx: the last spacing is 1.5 dx", or empty when whole.
    std::string note(int axis) const;
};

// The lattice along [lo, hi]; FatalError naming the keyword when the extent is under half a
// spacing or more spacings than an int holds.
LatticeAxis latticeAxis(const Dictionary& dict, const std::string& keyword, double lo, double hi, double dx);

// The lattice along each axis of the box [lo, hi] of `dict` (errors name its keyword max), with
// a note in `notes` for each axis whose last spacing is adjusted.
template <int D>
std::array<LatticeAxis, D> boxAxes(const Dictionary& dict, const Vec<D>& lo, const Vec<D>& hi, double dx, std::vector<std::string>& notes);

}  // namespace sph
