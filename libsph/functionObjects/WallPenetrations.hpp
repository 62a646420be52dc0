// wallPenetrations: fluid particles that have passed a wall, counted at every execution (every
// step by default, so a leak between written times is seen), written to
// postProcessing/<name>/<t0>/penetrations.dat: time, the count, and the largest count so far.
// A fluid particle i has passed the wall when, for the nearest first-layer wall particle j
// within the kernel support (any patch), (x_i - x_j) . n_j < 0: it lies behind the layer of
// particles on (correction, repulsion) or nearest (dummy, dynamic) the wall surface; and, where
// the wall turns away from the fluid (a convex edge or corner), behind every first-layer
// particle k there too: i in front of a k with (x_k - x_j) . (n_k - n_j) > 0 is outside the
// solid, between the edge particle's bisector plane and the faces (the nearest-plane test alone
// counted fluid resting against a box's edges as behind it); and within j's spacing s_j of it
// along its plane, |(x_i - x_j) - ((x_i - x_j) . n_j) n_j| <= s_j: farther, i is beyond the
// wall's free end (a splash over an open tank's top), since along a wall the nearest particle
// is at most s_j/2 (2D) or s_j/sqrt(2) (3D) away. A particle that has been beyond a free end is
// not counted while it stays behind a wall (it came down the wall's back, outside the tank)
// until it is in front of one again: the object remembers such particles by id from execution
// to execution, so a restart forgets them. Where the leaks are: behindWall.dat beside it lists
// each particle the first time it is counted (time, id, position), for ParaView's selection by id.
// Example (system/controlDict, functions):
//   leaks { type wallPenetrations; }
#pragma once

#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <cstdint>
#include <unordered_set>

namespace sph {

template <int D>
class WallPenetrations : public FunctionObject<D> {
public:
    WallPenetrations(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override { return "wallPenetrations: fluid particles behind a wall, every execution"; }
    void execute(const FluidSystemView<D>& system, double t) override;

    // The number of fluid particles this process owns behind a wall in `system` now, not
    // excepting any that came around a free end.
    static std::size_t count(const FluidSystemView<D>& system);

private:
    const Reductions& reductions_;  // over the processes that share the particles
    TimeSeriesFile out_;
    TimeSeriesFile firstFound_;  // behindWall.dat
    std::size_t most_ = 0;
    std::unordered_set<std::int64_t> aroundFreeEnd_;  // ids, alike on every process
    std::unordered_set<std::int64_t> listed_;         // ids in behindWall.dat, alike on every process
};

}  // namespace sph
