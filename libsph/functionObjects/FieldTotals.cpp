#include "functionObjects/FieldTotals.hpp"

#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
FieldTotals<D>::FieldTotals(const Dictionary&, const FunctionObjectContext<D>& context) {
    std::string header = "# time mass kineticEnergy";
    for (int d = 0; d < D; ++d) header += fmt::format(" momentum_{}", "xyz"[d]);
    out_ = TimeSeriesFile(context.outputDirectory, "totals.dat", header);
}

template <int D>
void FieldTotals<D>::execute(const FluidSystemView<D>& system, double t) {
    const auto& m = system.fluid[fields::mass];
    const auto& v = system.fluid[fields::velocity];
    double mass = 0.0, energy = 0.0;
    Vec<D> momentum = Vec<D>::Zero();
    for (std::size_t i = 0; i < system.fluid.ownedCount(); ++i) {
        mass += m[i];
        energy += 0.5 * m[i] * v[i].squaredNorm();
        momentum += m[i] * v[i];
    }
    out_.append(fmt::format("{:.9g} {:.12g} {:.9g} {:.9g}", t, mass, energy, fmt::join(momentum, " ")));
}

template class FieldTotals<1>;
template class FieldTotals<2>;
template class FieldTotals<3>;

}  // namespace sph
