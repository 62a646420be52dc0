// probes: fluid fields at fixed points over time, by kernel interpolation (KernelInterpolation.hpp;
// a dry probe reads 0). Writes postProcessing/<name>/<t0>/<field>.dat: time, then one column per
// probe. With a reference (ReferenceSeries.hpp; one field only) each probe is compared with its
// column of the file over time. A probe outside the domain is an error before the first step.
// Fields: p, rho, U (magnitude), Ux, Uy, Uz.
// Example (system/controlDict, functions):
//   wallPressure
//   {
//       type probes; fields (p); points ((0.83 0.5 0.021) (0.83 0.5 0.061)); executeInterval 0.001;
//       reference { file "reference/pressure.csv"; time t; columns (P1 P2); scale 1e4; }
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
class Probes : public FunctionObject<D> {
public:
    Probes(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    // The fields at the probes, [field][probe] (exposed for tests).
    std::vector<std::vector<double>> sample(const FluidSystemView<D>& system) const;

private:
    std::vector<Vec<D>> points_;
    std::vector<std::string> fields_;
    std::vector<TimeSeriesFile> out_;  // one per field
    std::optional<ReferenceSeries> reference_;
    const Reductions& reductions_;
};

}  // namespace sph
