// Which side of a wall a point lies on, judged from the wall particles near it (their normals
// point into the fluid). Read by wallPenetrations (fluid through a wall during a
// run) and by the generator (a patch facing away from its fluid, or with fluid on both sides).
#pragma once

#include "core/Vector.hpp"

#include <cstdint>
#include <limits>
#include <optional>

namespace sph {

struct WallSide {
    std::uint32_t nearestWall;
    bool behind;
    bool beyondFreeEnd = false;  // behind the nearest particle's plane, but past the wall's end
};

// forEachWallParticle(visit) calls visit(j, x - x_j, |x - x_j|^2) for every wall particle j near
// the point x; no wall particle near it gives nothing. `layer` (or null: one layer) numbers
// each particle's layer from the wall surface.
// The point is behind the wall if it lies behind the nearest particle's plane and, where the
// wall turns away from the fluid (a convex edge: the normals part along the wall,
// (x_k - x_j) . (n_k - n_j) > 0 for k in the nearest's layer), behind every such neighbour's
// plane too: the solid is behind all of them, so a point in front of any is outside, in the
// corner between the faces and the plane of the edge's own particle, whose normal is the
// faces' mean. (Across layers the rule would not hold: a thin solid's particles from the far
// face have the opposite normal.) Nor is a point behind the wall that lies more than the nearest
// particle's spacing along its plane from it: along a wall the nearest particle is at most
// half a spacing (2D) or s/sqrt(2) (3D, a square lattice) away along the plane, so such a point
// is beyond the wall's free end (a tank's open top, a baffle's tip), where no wall holds it.
template <int D, class ForEachWallParticle>
std::optional<WallSide> wallSide(const Vec<D>* normal, const double* spacing, const int* layer, ForEachWallParticle&& forEachWallParticle) {
    double nearest = std::numeric_limits<double>::infinity();
    double side = 1.0;
    std::optional<std::uint32_t> nearestWall;
    Vec<D> fromNearest = Vec<D>::Zero();
    forEachWallParticle([&](std::uint32_t j, const Vec<D>& r, double r2) {
        // Of equidistant particles the one the point lies behind wins: the visiting order does not count.
        if (r2 > nearest || (r2 == nearest && r.dot(normal[j]) >= side)) return;
        nearest = r2;
        side = r.dot(normal[j]);
        nearestWall = j;
        fromNearest = r;
    });
    if (!nearestWall) return std::nullopt;
    if (side >= 0.0) return WallSide{*nearestWall, false};
    bool inFrontOfAConvexNeighbour = false;
    forEachWallParticle([&](std::uint32_t k, const Vec<D>& r, double) {
        if ((!layer || layer[k] == layer[*nearestWall]) && r.dot(normal[k]) >= 0.0 && (fromNearest - r).dot(normal[k] - normal[*nearestWall]) > 0.0)
            inFrontOfAConvexNeighbour = true;
    });
    if (inFrontOfAConvexNeighbour) return WallSide{*nearestWall, false};
    // A free end's particles share one normal (no convex neighbour): only a point behind every
    // plane near it can lie past one, not one beside a convex edge.
    const Vec<D> alongThePlane = fromNearest - side * normal[*nearestWall];
    const bool beyondFreeEnd = alongThePlane.squaredNorm() > spacing[*nearestWall] * spacing[*nearestWall];
    return WallSide{*nearestWall, !beyondFreeEnd, beyondFreeEnd};
}

}  // namespace sph
