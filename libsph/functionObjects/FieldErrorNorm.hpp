// errorNorm: a fluid field at every fluid particle against an analytic solution
// (analytic/AnalyticSolution.hpp), e_i = |u_i - u(x_i, t)| for U, p_i - p(x_i, t) for p.
// Each execution appends the norms over the particles to postProcessing/<name>/<t0>/error.dat
// (time L1 L2 Linf); the run's summary reports the space-time norms over every execution
// (L1: mean of |e| over particles and times; L2: root mean square; Linf: largest), each
// divided by `scale`. For p, `subtractMean yes` compares p - mean(p) with p_exact - mean(p_exact)
// (WCSPH's background pressure is an arbitrary constant).
// Example (system/controlDict, functions):
//   velocityError
//   {
//       type errorNorm; field U; scale 1; executeInterval 0.1;
//       solution { type taylorGreen; U 1; L 1; nu 0.01; }
//   }
#pragma once

#include "analytic/AnalyticSolution.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <memory>

namespace sph {

template <int D>
class FieldErrorNorm : public FunctionObject<D> {
public:
    FieldErrorNorm(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    // The norms over the particles now (exposed for tests).
    ErrorNorms norms(const FluidSystemView<D>& system, double t) const;

private:
    const Reductions& reductions_;  // over the processes that share the particles
    // Adds each particle's error to `accumulator`, every process's (collective).
    void accumulate(const FluidSystemView<D>& system, double t, ErrorAccumulator& accumulator) const;

    std::string field_, solutionType_;
    std::unique_ptr<AnalyticSolution<D>> solution_;
    double scale_, rho0_;
    bool subtractMean_;
    TimeSeriesFile out_;
    ErrorAccumulator overRun_;
};

}  // namespace sph
