#include "functionObjects/WallPenetrations.hpp"

#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace sph {

template <int D>
WallPenetrations<D>::WallPenetrations(const Dictionary&, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions), out_(context.series("penetrations.dat", "# time behindWall mostSoFar")) {}

template <int D>
std::size_t WallPenetrations<D>::count(const FluidSystemView<D>& system) {
    const std::size_t n = system.fluid.ownedCount();
    const Vec<D>* x = system.fluid.position.data();
    const Vec<D>* normal = system.walls[fields::normal].data();
    const int* layer = system.walls.optionalData(fields::layer);
    // The wall-particle patches share one cell list; each wall-force patch has its own.
    std::vector<const CellLinkedList<D>*> lists{&system.wallCells};
    for (const Patch<D>& patch : system.patches)
        if (patch.cells) lists.push_back(&*patch.cells);
    const double radius = system.supportRadius;
    const auto forEachFirstLayerParticle = [&](const Vec<D>& xi, auto&& visit) {
        for (const CellLinkedList<D>* list : lists)
            if (list->anyPointNear(xi))
                list->forEachNeighbour(xi, radius, [&](std::uint32_t j, const Vec<D>& r, double r2) {
                    if (!layer || layer[j] == 0) visit(j, r, r2);
                });
    };
    std::size_t behind = 0;
#pragma omp parallel for schedule(static) reduction(+ : behind)
    for (std::size_t i = 0; i < n; ++i) {
        if (!system.ownsFluid(i)) continue;
        double nearest = std::numeric_limits<double>::infinity();
        double side = 1.0;
        std::uint32_t nearestWall = 0;
        Vec<D> fromNearest = Vec<D>::Zero();
        forEachFirstLayerParticle(x[i], [&](std::uint32_t j, const Vec<D>& r, double r2) {
            // Of equidistant particles the one it lies behind wins: the count ignores visiting order.
            if (r2 > nearest || (r2 == nearest && r.dot(normal[j]) >= side)) return;
            nearest = r2;
            side = r.dot(normal[j]);
            nearestWall = j;
            fromNearest = r;
        });
        if (side >= 0.0) continue;
        // Behind the nearest particle's plane. Where the wall turns away from the fluid (a convex
        // edge: the normals part along the wall, (x_k - x_j) . (n_k - n_j) > 0) the solid is behind
        // every plane there, so fluid in front of any of them is outside: it sits in the corner
        // between the bisector's plane and the faces, nearer the edge's particle than the faces'.
        bool inFrontOfAConvexNeighbour = false;
        forEachFirstLayerParticle(x[i], [&](std::uint32_t k, const Vec<D>& r, double) {
            if (r.dot(normal[k]) >= 0.0 && (fromNearest - r).dot(normal[k] - normal[nearestWall]) > 0.0) inFrontOfAConvexNeighbour = true;
        });
        if (!inFrontOfAConvexNeighbour) ++behind;
    }
    return behind;
}

template <int D>
void WallPenetrations<D>::execute(const FluidSystemView<D>& system, double t) {
    const auto behind = static_cast<std::size_t>(reductions_.sum(static_cast<double>(count(system))));
    most_ = std::max(most_, behind);
    out_.append(fmt::format("{:.9g} {} {}", t, behind, most_));
}

template class WallPenetrations<1>;
template class WallPenetrations<2>;
template class WallPenetrations<3>;

}  // namespace sph
