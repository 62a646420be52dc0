// wallPressure: pressure sensors on a wall patch, over time, as an experiment's transducers
// read it: each sensor averages the pressure of the patch's wall particles of layer 0 within its
// footprint, a segment along the wall in 2D, a disc in 3D, in the plane normal to the normal n
// of the particle nearest the centre c: x_j - c less its part along n at most size/2 long, its
// part along n at most a spacing (layer 0 lies half a spacing behind the surface on layered
// walls), weighted by their areas A_j:
//   p_sensor = sum_j A_j p_j / sum_j A_j
// (equal weights where the footprint holds only particles without area); a sensor smaller than
// the spacing reads the nearest surface particle. p_j is the wall particle's own pressure where
// the patch's model sets one (dummy particles, dynamic boundary, the deficiency correction's
// extrapolated p_j), else the fluid extrapolated to it as Adami et al. (2012) do:
//   p_j = [sum_f p_f W_jf + (g - a_j) . sum_f rho_f (x_j - x_f) W_jf] / sum_f W_jf.
// `source fluid` extrapolates on every patch: dynamic boundary particles' own pressure is the
// repulsion that holds the fluid off, not the fluid's (damBreakWallPressure2D, H/dx = 20: 2-14x
// the fluid's dx/2 in front of the wall after the impact; their density also starts hydrostatic
// where no water stands).
// Each sensor's particles are chosen once, where the patch was generated (its initial
// positions on a moving patch), so the sensor moves and deforms with the patch.
// `timeWindow` T > 0 adds a trailing moving average over the last T of simulated time (the
// trapezoidal rule over the executions; a post-processing filter of the signal, not a change to
// the dynamics; it starts afresh with each run), which a reference then compares with.
// Writes postProcessing/<name>/<t0>/pressure.dat: time, one column per sensor, then with
// timeWindow one averaged column per sensor. A sensor farther than its size and a spacing from
// the patch's surface, an unknown patch or a size that is not positive is an error before the
// first step.
// Example (system/controlDict, functions; damBreakWallPressure2D's sensors P1 and P2, the
// reference De Courcy et al. 2024's curve in units of T = t sqrt(g/H) and rho g H, H = 0.6 m):
//   wallSensors
//   {
//       type wallPressure; patch tank; points ((3.21 0.006) (3.21 0.03)); size 0.009;
//       timeWindow 0.0247;   // default 0: no average
//       source model;        // default; or fluid
//       reference { file "deCourcy2024P1P2.csv"; time T; columns (P1 P2); timeScale 0.2473; valueScale 5886; }
//   }
#pragma once

#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/ReferenceSeries.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace sph {

template <int D>
class WallPressureSensors : public FunctionObject<D> {
public:
    WallPressureSensors(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    std::vector<double> pressures(const FluidSystemView<D>& system, double t) const;  // one per sensor, unfiltered (exposed for tests)
    // The trailing average of the signal over timeWindow, after adding the sample (t, values).
    std::vector<double> averaged(double t, const std::vector<double>& values);

private:
    const Reductions& reductions_;  // over the processes that share the particles
    double extrapolatedPressure(const FluidSystemView<D>& system, std::size_t wall, double t) const;
    struct WallCandidate {
        double gap;               // from the sensor
        Vec<D> position, normal;  // where the patch was generated
        double id;
    };
    // Collective: the surface particle nearest to `point` over every process's `surface`.
    WallCandidate nearestSurfaceParticle(const FluidSystemView<D>& system, const std::vector<std::size_t>& surface, const Vec<D>& point) const;

    std::vector<Vec<D>> points_;
    double size_, window_;
    std::string patchName_;
    std::size_t patch_ = 0;                                                 // index into the system's patches
    std::unordered_map<std::int64_t, std::vector<std::size_t>> sensorsOf_;  // by wall particle id: the sensors it belongs to
    std::vector<std::size_t> memberCount_;                                  // per sensor: its wall particles
    bool modelSetsPressure_ = false;
    std::deque<std::pair<double, std::vector<double>>> history_;  // the samples within the window
    TimeSeriesFile out_;
    std::optional<ReferenceSeries> reference_;
};

}  // namespace sph
