#include "functionObjects/WallPenetrations.hpp"

#include "neighbourSearch/WallSide.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sph {

namespace {

// visit(i, side) for every fluid particle i this process owns that has a first-layer wall
// particle within the kernel support (any patch), in parallel.
template <int D, class Visit>
void forEachOwnedFluidBesideAWall(const FluidSystemView<D>& system, Visit&& visit) {
    const std::size_t n = system.fluid.ownedCount();
    const Vec<D>* x = system.fluid.position.data();
    const Vec<D>* normal = system.walls[fields::normal].data();
    const double* spacing = system.walls[fields::spacing].data();
    const int* layer = system.walls.optionalData(fields::layer);
    // The wall-particle patches share one cell list; each wall-force patch has its own.
    std::vector<const CellLinkedList<D>*> lists{&system.wallCells};
    for (const Patch<D>& patch : system.patches)
        if (patch.cells) lists.push_back(&*patch.cells);
    const double radius = system.supportRadius;
    const auto forEachFirstLayerParticle = [&](const Vec<D>& xi, auto&& visitWall) {
        for (const CellLinkedList<D>* list : lists)
            if (list->anyPointNear(xi))
                list->forEachNeighbour(xi, radius, [&](std::uint32_t j, const Vec<D>& r, double r2) {
                    if (!layer || layer[j] == 0) visitWall(j, r, r2);
                });
    };
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        if (!system.ownsFluid(i)) continue;
        const auto side = wallSide<D>(normal, spacing, nullptr, [&](auto&& visitWall) { forEachFirstLayerParticle(x[i], visitWall); });
        if (side) visit(i, *side);
    }
}

}  // namespace

template <int D>
WallPenetrations<D>::WallPenetrations(const Dictionary&, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions),
      out_(context.series("penetrations.dat", "# time behindWall mostSoFar")),
      firstFound_(context.series("behindWall.dat", "# time id position: each fluid particle the first time it is behind a wall")) {}

template <int D>
std::size_t WallPenetrations<D>::count(const FluidSystemView<D>& system) {
    std::size_t behind = 0;
    forEachOwnedFluidBesideAWall(system, [&](std::size_t, const WallSide& side) {
        if (side.behind) {
#pragma omp atomic
            ++behind;
        }
    });
    return behind;
}

template <int D>
void WallPenetrations<D>::execute(const FluidSystemView<D>& system, double t) {
    const std::int64_t* id = system.fluid.globalId.data();
    std::size_t behind = 0;
    // Ids that came around a free end (id + 1) and that are in front of a wall again (-(id + 1)):
    // rare, so collected under a lock and shared with every process.
    std::vector<double> changes;
    std::vector<double> found;  // id, then the position, of each particle counted for the first time
    const Vec<D>* x = system.fluid.position.data();
    forEachOwnedFluidBesideAWall(system, [&](std::size_t i, const WallSide& side) {
        const bool remembered = !aroundFreeEnd_.empty() && aroundFreeEnd_.contains(id[i]);  // mostly empty: no lookup
        const bool inFront = !side.behind && !side.beyondFreeEnd;
        if (side.behind && !remembered) {
#pragma omp atomic
            ++behind;
            if (!listed_.contains(id[i])) {
#pragma omp critical(wallPenetrationsFound)
                {
                    found.push_back(static_cast<double>(id[i]));
                    for (int d = 0; d < D; ++d) found.push_back(x[i][d]);
                }
            }
        }
        if ((side.beyondFreeEnd && !remembered) || (inFront && remembered)) {
#pragma omp critical(wallPenetrationsChanges)
            changes.push_back(static_cast<double>(side.beyondFreeEnd ? id[i] + 1 : -(id[i] + 1)));
        }
    });
    for (const double change : reductions_.gather(changes)) {
        const auto changed = static_cast<std::int64_t>(change);
        if (changed > 0)
            aroundFreeEnd_.insert(changed - 1);
        else
            aroundFreeEnd_.erase(-changed - 1);
    }
    // By id, so that the file does not depend on the threads' or ranks' order.
    const std::vector<double> everyFound = reductions_.gather(found);
    std::vector<std::size_t> byId;
    for (std::size_t at = 0; at < everyFound.size(); at += D + 1) byId.push_back(at);
    std::sort(byId.begin(), byId.end(), [&](std::size_t a, std::size_t b) { return everyFound[a] < everyFound[b]; });
    for (const std::size_t at : byId) {
        listed_.insert(static_cast<std::int64_t>(everyFound[at]));
        std::string line = fmt::format("{:.9g} {}", t, static_cast<std::int64_t>(everyFound[at]));
        for (int d = 0; d < D; ++d) line += fmt::format(" {:.9g}", everyFound[at + 1 + static_cast<std::size_t>(d)]);
        firstFound_.append(line);
    }
    const auto total = static_cast<std::size_t>(reductions_.sum(static_cast<double>(behind)));
    most_ = std::max(most_, total);
    out_.append(fmt::format("{:.9g} {} {}", t, total, most_));
}

template class WallPenetrations<1>;
template class WallPenetrations<2>;
template class WallPenetrations<3>;

}  // namespace sph
