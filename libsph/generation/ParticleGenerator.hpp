// generateParticles: builds the initial state 0/fluid.vtu and 0/walls.vtu from
// system/generateParticlesDict (and rho0, gravity and the equation of state from
// constant/fluidProperties):
//   dimension  2;
//   spacing    0.01;                              // dx
//   domain     { min (-0.1 -0.1); max (1.7 1.0); } // every particle must lie inside
//   initialPressure hydrostatic;                  // or none (default): p = rho0 |g| (H - z),
//                                                 // H the top of each fluid region; or analytic:
//                                                 // the pressure of each region's velocity solution
//   fluid      { <name> { type box; ... } ... }    // see FluidRegions.hpp
//   boundaries { <patch> { type boxWalls; ... } ... }  // see WallPatches.hpp
// Fluid particles inside an obstacle, or closer than dx/2 to a wall particle, are dropped, but
// for those in front of a one-layer wall, which are moved out to dx/2 from it.
// Mass is rho0 dx^D; the density follows the initial pressure through the equation of state.
#pragma once

#include "generation/FluidRegions.hpp"

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace sph {

struct GenerationSummary {
    int dimension = 0;
    std::size_t fluidParticles = 0;
    std::size_t wallParticles = 0;
    std::size_t droppedFluidParticles = 0;
    std::vector<std::string> warnings;  // what may be a mistake but can be meant (printed by generateParticles)
    std::vector<std::string> notes;     // what the generator adjusted (a box's last spacing)
};

// One of several generators (generateParticles -parallel under mpirun): each fills its rows of
// every fluid region's lattice (LatticeShare) and writes them as its piece of 0/fluid.pvtu; each
// lays out every wall (a surface, small beside the fluid) and writes a block of them as its
// piece of 0/walls.pvtu. The pieces carry each particle's place in the serial generator's order
// (orderCell 0, orderRank its id), so that a run from them equals a run from the serial state.
struct GenerationShare {
    LatticeShare rows;
    // Every rank's values, rank 0's first (each rank passes as many).
    std::function<std::vector<double>(std::span<const double>)> gatherToAll;
    // Runs `body` on this rank; a FatalError on any rank stops every rank with its message.
    std::function<void(const std::function<void()>& body)> together;
};

// Writes <case>/0/ (with `share`, this rank's pieces; the summary counts every rank's
// particles); refuses to replace an existing 0/ state unless `overwrite`, which also removes the
// later times the solver wrote from the state replaced (it would resume from them).
GenerationSummary generateParticles(const std::filesystem::path& caseDirectory, bool overwrite, const GenerationShare* share = nullptr);

}  // namespace sph
