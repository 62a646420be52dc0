// probes: fluid fields at fixed points over time, by kernel interpolation (KernelInterpolation.hpp;
// a dry probe reads 0). Writes postProcessing/<name>/<t0>/<field>.dat: time, then one column per
// probe. With a reference (ReferenceSeries.hpp; one field only) each probe is compared with its
// column of the file over time. With `patch`, the probes move with that patch's motion (a sensor
// on a sloshing tank's wall, a point in a moving box): each point is a material point of the
// patch, given where the patch was generated; velocities stay those of the lab frame. A probe
// outside the domain or an unknown patch is an error before the first step.
// Fields: p, rho, U (magnitude), Ux, Uy, Uz.
// Example (system/controlDict, functions):
//   wallPressure
//   {
//       type probes; fields (p); points ((0.83 0.5 0.021) (0.83 0.5 0.061)); executeInterval 0.001;
//       patch box;           // default: fixed in the lab frame
//       reference { file "reference/pressure.csv"; time t; columns (P1 P2); scale 1e4; }
//   }
#pragma once

#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/ReferenceSeries.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sph {

template <int D>
class Probes : public FunctionObject<D> {
public:
    Probes(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    // The fields at the probes at time t, [field][probe] (exposed for tests).
    std::vector<std::vector<double>> sample(const FluidSystemView<D>& system, double t) const;

private:
    std::vector<Vec<D>> points_;
    std::string patchName_;
    const PatchMotion<D>* motion_ = nullptr;  // the frame the probes move with; none: the lab
    std::vector<std::string> fields_;
    std::vector<TimeSeriesFile> out_;  // one per field
    std::optional<ReferenceSeries> reference_;
    const Reductions& reductions_;
};

}  // namespace sph
