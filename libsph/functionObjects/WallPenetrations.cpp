#include "functionObjects/WallPenetrations.hpp"

#include "neighbourSearch/WallSide.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>

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
        const auto side = wallSide<D>(normal, nullptr, [&](auto&& visit) { forEachFirstLayerParticle(x[i], visit); });
        if (side && side->behind) ++behind;
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
