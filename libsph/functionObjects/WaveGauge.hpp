// waveGauge: free-surface elevation at gauges over time, read where the kernel-interpolated
// fluid volume fraction
//   phi(x) = sum_j V_j W(|x - x_j|),   V_j = m_j / rho_j
// (about 1 inside the fluid, 1/2 on a flat surface) falls through `threshold` along the line
// upwards (against gravity) from each gauge's point: the topmost crossing, so that a splashed
// particle or a thin jet (phi below the threshold) does not read as the level. The line is
// scanned downwards in steps of dx/4 from its top and the crossing bisected to dx/1000; in a
// decomposed run every gauge together takes one collective for the scan and one per bisection
// round. In the manner of DualSPHysics' swl gauge and OpenFOAM's interfaceHeight.
// With `patch`, the gauges move with that patch's motion (a sloshing tank's wall gauges): each
// point is a material point of the patch, the line turns with a rotating patch.
// Writes postProcessing/<name>/<t0>/elevation.dat: time, then one column per gauge, the height
// of the crossing above the gauge's point (0 where the line is dry). With a reference
// (ReferenceSeries.hpp) each gauge is compared with its column over time. A gauge outside the
// domain, a threshold outside (0, 1), an unknown patch or a case without gravity is an error
// before the first step.
// Example (system/controlDict, functions):
//   gauges
//   {
//       type waveGauge; points ((0.05 0)); executeInterval 0.005;
//       patch tank;          // default: fixed in the lab frame
//       threshold 0.5;       // default
//       length 1.2;          // default: to the domain's boundary
//       reference { file "faltinsen2000Fig7.csv"; time t; columns (eta); }
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
class PatchMotion;

template <int D>
class WaveGauge : public FunctionObject<D> {
public:
    WaveGauge(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    std::vector<double> elevations(const FluidSystemView<D>& system, double t) const;  // one per gauge (exposed for tests)

private:
    const Reductions& reductions_;  // over the processes that share the particles
    std::vector<Vec<D>> points_;
    std::vector<double> lengths_;  // of each gauge's line
    Vec<D> up_;
    double threshold_, step_;
    std::string patchName_;
    const PatchMotion<D>* motion_ = nullptr;  // the frame the gauges move with; none: the lab
    TimeSeriesFile out_;
    std::optional<ReferenceSeries> reference_;
};

}  // namespace sph
