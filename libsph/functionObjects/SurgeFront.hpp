// surgeFront: the leading fluid particle's distance from `origin` along `direction`, over time
// (dam-break surge front, Martin & Moyce 1952). Writes postProcessing/<name>/<t0>/surgeFront.dat
// with columns: time, front. With a reference (ReferenceSeries.hpp, one column) the front is
// compared with it over time.
// Example (system/controlDict, functions):
//   front
//   {
//       type surgeFront; origin (0 0); direction (1 0); executeInterval 0.005;
//       reference { file "martinMoyce1952Front.csv"; time T; columns (Z); timeScale 0.05397; valueScale 0.05715; scale 0.05715; }
//   }
#pragma once

#include <optional>

#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/ReferenceSeries.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

namespace sph {

template <int D>
class SurgeFront : public FunctionObject<D> {
public:
    SurgeFront(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

private:
    const Reductions& reductions_;  // over the processes that share the particles
    Vec<D> origin_, direction_;
    TimeSeriesFile out_;
    std::optional<ReferenceSeries> reference_;
};

}  // namespace sph
