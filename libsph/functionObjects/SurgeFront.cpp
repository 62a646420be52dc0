#include "functionObjects/SurgeFront.hpp"

#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>
#include <limits>

namespace sph {

template <int D>
SurgeFront<D>::SurgeFront(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions), origin_(dict.getVector<D>("origin")), direction_(dict.getVector<D>("direction")) {
    if (!(direction_.norm() > 0.0)) dict.fail("direction", "must not be the zero vector");
    direction_.normalize();
    out_ = context.series("surgeFront.dat", "# time front");
    if (const Dictionary* reference = dict.findSubDict("reference"))
        reference_.emplace(*reference, context.caseDirectory, std::vector<std::string>{"front"});
}

template <int D>
std::string SurgeFront<D>::describe() const {
    return fmt::format("surgeFront: origin ({:g}), direction ({:g}){}", fmt::join(origin_, " "), fmt::join(direction_, " "),
                       reference_ ? ", " + reference_->describe() : "");
}

template <int D>
void SurgeFront<D>::execute(const FluidSystemView<D>& system, double t) {
    double front = -std::numeric_limits<double>::infinity();
    const auto& x = system.fluid.position;
    for (std::size_t i = 0; i < system.fluid.ownedCount(); ++i)
        if (system.ownsFluid(i)) front = std::max(front, (x[i] - origin_).dot(direction_));
    front = reductions_.max(front);
    out_.append(fmt::format("{:.9g} {:.9g}", t, front));
    if (reference_) reference_->compare(t, {front});
}

template <int D>
std::vector<ReportedError> SurgeFront<D>::errors() const {
    return errorsOf(reference_);
}

template class SurgeFront<1>;
template class SurgeFront<2>;
template class SurgeFront<3>;

}  // namespace sph
