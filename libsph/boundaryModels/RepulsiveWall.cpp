#include "boundaryModels/RepulsiveWall.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

RepulsionLaw readRepulsionLaw(const Dictionary& dict, const ModelContext& context) {
    const std::string type = dict.get<std::string>("type");
    if (type == "monaghanKajtar") {
        const std::string form = dict.getOrDefault<std::string>("form", "square");
        if (form != "square" && form != "shifted") dict.fail("form", "expected square or shifted, found '" + form + "'");
        const double shift = form == "shifted" ? dict.getNonNegativeOrDefault("shift", 0.5 * context.dx) : 0.0;
        return MonaghanKajtar2009{dict.getPositive("K"), context.dx, shift, form == "shifted" ? 0.1 * context.dx : 0.0};
    }
    if (type == "lennardJones") {
        const int p1 = dict.getOrDefault("p1", 12), p2 = dict.getOrDefault("p2", 4);
        if (!(p1 > p2 && p2 > 0)) dict.fail("p1", fmt::format("needs p1 > p2 > 0, found p1 {} and p2 {}", p1, p2));
        return LennardJonesMonaghan1994{dict.getPositive("Dc"), dict.getPositiveOrDefault("r0", context.dx), p1, p2};
    }
    throw FatalError(dict.entry("type").tokens().front().where,
                     "unknown repulsion '" + type + "'; valid repulsion names are:\n    lennardJones\n    monaghanKajtar");
}

std::string describe(const RepulsionLaw& law) {
    return std::visit(
        [](const auto& l) -> std::string {
            using L = std::decay_t<decltype(l)>;
            if constexpr (std::is_same_v<L, MonaghanKajtar2009>)
                return l.shift > 0.0 ? fmt::format("monaghanKajtar: K {:g}, shifted form, shift {:g}", l.K, l.shift)
                                     : fmt::format("monaghanKajtar: K {:g}, |r|^2 form", l.K);
            else
                return fmt::format("lennardJones: Dc {:g}, r0 {:g}, p1 {}, p2 {}", l.Dc, l.r0, l.p1, l.p2);
        },
        law);
}

double repulsionRange(const RepulsionLaw& law, double support) {
    if (const auto* lennardJones = std::get_if<LennardJonesMonaghan1994>(&law)) return lennardJones->range();
    return support;
}

template <int D>
void addRepulsion(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, const RepulsionLaw& law) {
    const std::size_t n = view.fluid.ownedCount();
    const Vec<D>* x = view.fluid.position.data();
    const double* mFluid = view.fluid[fields::mass].data();
    Vec<D>* a = view.fluid[fields::acceleration].data();
    const double* mWall = view.walls[fields::mass].data();
    const double* spacing = view.walls[fields::spacing].data();
    std::visit(
        [&](const auto& kernel, const auto& l) {
            using L = std::decay_t<decltype(l)>;
            const double inverseW0 = 1.0 / kernel.value(0.0);
            const double range = repulsionRange(law, view.supportRadius);
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i) {
                if (!patchCells.anyPointNear(x[i])) continue;
                Vec<D> sum = Vec<D>::Zero();
                patchCells.forEachNeighbour(x[i], range, [&](std::uint32_t k, const Vec<D>& r, double r2) {
                    const double distance = std::sqrt(r2);
                    if constexpr (std::is_same_v<L, MonaghanKajtar2009>)
                        sum += l.acceleration(r, distance, kernel.value(distance) * inverseW0, spacing[k], mFluid[i], mWall[k]);
                    else
                        sum += l.acceleration(r, distance);
                });
                a[i] += sum;
            }
        },
        view.kernel, law);
}

template void addRepulsion<1>(const BoundaryView<1>&, const CellLinkedList<1>&, const RepulsionLaw&);
template void addRepulsion<2>(const BoundaryView<2>&, const CellLinkedList<2>&, const RepulsionLaw&);
template void addRepulsion<3>(const BoundaryView<3>&, const CellLinkedList<3>&, const RepulsionLaw&);

}  // namespace sph
