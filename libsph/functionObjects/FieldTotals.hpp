// fieldTotals: conserved and watched totals of the fluid over time, written to
// postProcessing/<name>/<t0>/totals.dat: time, mass sum m, kinetic energy sum m|u|^2/2 and
// momentum sum m u (one column per component). Mass is constant unless particles are lost; a
// closed inviscid tank keeps momentum bounded and energy non-increasing.
// Example (system/controlDict, functions):
//   totals { type fieldTotals; executeInterval 0.01; }
#pragma once

#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

namespace sph {

template <int D>
class FieldTotals : public FunctionObject<D> {
public:
    FieldTotals(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override { return "fieldTotals: mass, kinetic energy, momentum"; }
    void execute(const FluidSystemView<D>& system, double t) override;

private:
    const Reductions& reductions_;  // over the processes that share the particles
    TimeSeriesFile out_;
};

}  // namespace sph
