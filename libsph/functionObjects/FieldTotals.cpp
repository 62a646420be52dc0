#include "functionObjects/FieldTotals.hpp"

#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <array>

namespace sph {

template <int D>
FieldTotals<D>::FieldTotals(const Dictionary&, const FunctionObjectContext<D>& context) : reductions_(context.reductions) {
    std::string header = "# time mass kineticEnergy";
    for (int d = 0; d < D; ++d) header += fmt::format(" momentum_{}", "xyz"[d]);
    out_ = context.series("totals.dat", header);
}

template <int D>
void FieldTotals<D>::execute(const FluidSystemView<D>& system, double t) {
    const auto& m = system.fluid[fields::mass];
    const auto& v = system.fluid[fields::velocity];
    // Mass, kinetic energy, momentum.
    std::array<ExactSum, 2 + D> totals;
    for (std::size_t i = 0; i < system.fluid.ownedCount(); ++i) {
        if (!system.ownsFluid(i)) continue;
        totals[0].add(m[i]);
        totals[1].add(0.5 * m[i] * v[i].squaredNorm());
        for (int d = 0; d < D; ++d) totals[2 + static_cast<std::size_t>(d)].add(m[i] * v[i][d]);
    }
    reductions_.sum(totals);
    Vec<D> momentum;
    for (int d = 0; d < D; ++d) momentum[d] = totals[2 + static_cast<std::size_t>(d)].value();
    out_.append(fmt::format("{:.9g} {:.12g} {:.9g} {:.9g}", t, totals[0].value(), totals[1].value(), fmt::join(momentum, " ")));
}

template class FieldTotals<1>;
template class FieldTotals<2>;
template class FieldTotals<3>;

}  // namespace sph
