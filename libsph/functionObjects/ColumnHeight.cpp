#include "functionObjects/ColumnHeight.hpp"

#include "functionObjects/FirstParticleSpacing.hpp"
#include "functionObjects/KernelInterpolation.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

template <int D>
ColumnHeight<D>::ColumnHeight(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions),
      points_(readSamplePoints(dict, "points", context.system, "gauge")),
      radius_(dict.getPositiveOrDefault("radius", context.system.smoothingLength)) {
    const FluidSystemView<D>& system = context.system;
    const Vec<D> g = system.gravity.full;
    if (!(g.norm() > 0.0)) dict.fail("type", "columnHeight measures against gravity, and this case has none");
    up_ = -g.normalized();
    halfSpacing_ = 0.5 * firstParticleSpacing(system, reductions_).value_or(0.0);
    std::string header = "# time";
    for (std::size_t k = 0; k < points_.size(); ++k) header += fmt::format(" h({:g})", fmt::join(points_[k], " "));
    out_ = context.series("height.dat", header);
    if (const Dictionary* reference = dict.findSubDict("reference")) {
        std::vector<std::string> quantities;
        for (std::size_t k = 0; k < points_.size(); ++k) quantities.push_back(fmt::format("height at gauge {}", k));
        reference_.emplace(*reference, context.caseDirectory, quantities);
    }
}

template <int D>
std::string ColumnHeight<D>::describe() const {
    return fmt::format("columnHeight: {} gauges, radius {:g}{}", points_.size(), radius_, reference_ ? ", " + reference_->describe() : "");
}

template <int D>
std::vector<double> ColumnHeight<D>::heights(const FluidSystemView<D>& system) const {
    std::vector<double> result(points_.size(), 0.0);
    const auto& x = system.fluid.position;
    for (std::size_t i = 0; i < system.fluid.ownedCount(); ++i)
        for (std::size_t k = 0; k < points_.size() && system.ownsFluid(i); ++k) {
            const Vec<D> offset = x[i] - points_[k];
            const double height = offset.dot(up_);
            if ((offset - height * up_).squaredNorm() < radius_ * radius_) result[k] = std::max(result[k], height + halfSpacing_);
        }
    reductions_.max(result);
    return result;
}

template <int D>
void ColumnHeight<D>::execute(const FluidSystemView<D>& system, double t) {
    const std::vector<double> h = heights(system);
    out_.append(fmt::format("{:.9g} {:.9g}", t, fmt::join(h, " ")));
    if (reference_) reference_->compare(t, h);
}

template <int D>
std::vector<ReportedError> ColumnHeight<D>::errors() const {
    return errorsOf(reference_);
}

template class ColumnHeight<1>;
template class ColumnHeight<2>;
template class ColumnHeight<3>;

}  // namespace sph
