#include "functionObjects/FieldErrorNorm.hpp"

#include "io/SelectByType.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <array>

namespace sph {

template <int D>
FieldErrorNorm<D>::FieldErrorNorm(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions),
      field_(dict.get<std::string>("field")),
      scale_(dict.getPositiveOrDefault("scale", 1.0)),
      rho0_(context.rho0),
      subtractMean_(dict.getOrDefault("subtractMean", false)) {
    const Dictionary& solution = dict.subDict("solution");
    solutionType_ = solution.get<std::string>("type");
    solution_ = selectByType(makeAnalyticSolutionRegistry<D>(), solution, solution);
    if (field_ != "U" && field_ != "p") dict.fail("field", fmt::format("unknown field '{}'; valid fields are: U, p", field_));
    if (field_ == "p" && !solution_->hasPressure())
        dict.fail("field", fmt::format("the {} solution has no pressure field; compare U", solutionType_));
    if (subtractMean_ && field_ != "p") dict.fail("subtractMean", "applies to the field p only");
    out_ = context.series("error.dat", fmt::format("# time L1 L2 Linf of {} - {}_exact, divided by {:g}", field_, field_, scale_));
}

template <int D>
std::string FieldErrorNorm<D>::describe() const {
    return fmt::format("errorNorm: {} against the {} solution, scale {:g}", field_, solutionType_, scale_);
}

template <int D>
void FieldErrorNorm<D>::accumulate(const FluidSystemView<D>& system, double t, ErrorAccumulator& accumulator) const {
    const auto& x = system.fluid.position;
    const std::size_t n = system.fluid.ownedCount();
    if (field_ == "U") {
        const auto& v = system.fluid[fields::velocity];
        for (std::size_t i = 0; i < n; ++i)
            if (system.ownsFluid(i)) accumulator.add((v[i] - solution_->velocity(x[i], t)).norm());
    } else {
        const auto& p = system.fluid[fields::pressure];
        const FlowConstants<D> constants{rho0_, system.gravity.at(t)};
        std::vector<double> difference(n);
        std::array<ExactSum, 2> total;  // of the differences, and the particles
        for (std::size_t i = 0; i < n; ++i) {
            if (!system.ownsFluid(i)) continue;
            difference[i] = p[i] - solution_->pressure(x[i], t, constants);
            total[0].add(difference[i]);
            total[1].add(1.0);
        }
        reductions_.sum(total);
        const double shift = subtractMean_ && total[1].value() > 0.0 ? total[0].value() / total[1].value() : 0.0;
        for (std::size_t i = 0; i < n; ++i)
            if (system.ownsFluid(i)) accumulator.add(difference[i] - shift);
    }
    accumulator.combine(reductions_);
}

template <int D>
ErrorNorms FieldErrorNorm<D>::norms(const FluidSystemView<D>& system, double t) const {
    ErrorAccumulator now;
    accumulate(system, t, now);
    return now.norms(scale_);
}

template <int D>
void FieldErrorNorm<D>::execute(const FluidSystemView<D>& system, double t) {
    ErrorAccumulator now;
    accumulate(system, t, now);
    overRun_.merge(now);
    const ErrorNorms norms = now.norms(scale_);
    out_.append(fmt::format("{:.9g} {:.6e} {:.6e} {:.6e}", t, norms.l1, norms.l2, norms.linf));
}

template <int D>
std::vector<ReportedError> FieldErrorNorm<D>::errors() const {
    return {{field_, overRun_.norms(scale_), fmt::format("scale {:g}, particles x times", scale_)}};
}

template class FieldErrorNorm<1>;
template class FieldErrorNorm<2>;
template class FieldErrorNorm<3>;

}  // namespace sph
