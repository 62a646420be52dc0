// columnHeight: water height at gauges over time (wave gauges, the SPHERIC Test 2 H1-H4): for
// each gauge point, the highest fluid particle within `radius` of the vertical through it, plus
// half a particle spacing, measured upwards (against gravity) from the point; 0 when dry.
// Writes postProcessing/<name>/<t0>/height.dat: time, then one column per gauge. With a
// reference (ReferenceSeries.hpp) each gauge is compared with its column over time. A gauge
// outside the domain, or a case without gravity, is an error before the first step.
// Example (system/controlDict, functions):
//   gauges
//   {
//       type columnHeight; points ((0.496 0.5 0) (0.992 0.5 0)); executeInterval 0.01;
//       radius 0.02;        // default: the smoothing length
//       reference { file "reference/heights.csv"; time t; columns (H1 H2); scale 0.55; }
//   }
#pragma once

#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/ReferenceSeries.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <optional>
#include <vector>

namespace sph {

template <int D>
class ColumnHeight : public FunctionObject<D> {
public:
    ColumnHeight(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    std::vector<double> heights(const FluidSystemView<D>& system) const;  // one per gauge (exposed for tests)

private:
    const Reductions& reductions_;  // over the processes that share the particles
    std::vector<Vec<D>> points_;
    Vec<D> up_;
    double radius_, halfSpacing_;
    TimeSeriesFile out_;
    std::optional<ReferenceSeries> reference_;
};

}  // namespace sph
