// lineSample: pressure, density and velocity along a line, interpolated from the fluid particles
// (KernelInterpolation.hpp). Each execution writes postProcessing/<name>/<t0>/<time>/line.csv
// (distance, position, p, rho, velocity[, p_ref]). With a hydrostaticReference it compares p with
// rho0 |g| (H - z) (analytic/HydrostaticPressure.hpp), and appends to error.dat the L2 and max
// error over the samples, normalised by rho0 |g| H; the run's summary reports the last execution's.
// With a reference profile (ReferenceSeries.hpp, Along::Coordinate) it compares one field at
// every sample with a CSV column interpolated at the sample's coordinate along `axis`; the
// summary reports the last execution's norms over the samples inside the profile's range.
// Example (system/controlDict, functions):
//   pressure
//   {
//       type lineSample; start (1 0); end (1 0.9); points 46; executeInterval 0.1;
//       hydrostaticReference { freeSurfaceHeight 0.9; }
//   }
//   uCentreLine
//   {
//       type lineSample; start (0.5 0); end (0.5 1); points 51; executeInterval 1;
//       reference { file "ghia1982U.csv"; coordinate Y; axis y; field Ux; columns (u_Re100); }
//   }
#pragma once

#include "analytic/HydrostaticPressure.hpp"
#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/ReferenceSeries.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

#include <optional>
#include <vector>

namespace sph {

template <int D>
class LineSample : public FunctionObject<D> {
public:
    LineSample(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override;
    void execute(const FluidSystemView<D>& system, double t) override;
    std::vector<ReportedError> errors() const override;

    struct Sample {
        Vec<D> position;
        double pressure, density;
        Vec<D> velocity;
    };
    // Interpolated values at the points (exposed for tests).
    std::vector<Sample> sample(const FluidSystemView<D>& system) const;

private:
    Vec<D> start_, end_;
    int points_;
    std::optional<HydrostaticPressure<D>> hydrostatic_;
    double rho0_;
    std::filesystem::path directory_;
    const Reductions& reductions_;
    TimeSeriesFile errorOut_;
    ErrorNorms last_;
    std::optional<ReferenceSeries> profile_;
    std::string profileField_;
    int profileAxis_ = 0;
    double time_ = 0.0;
};

}  // namespace sph
