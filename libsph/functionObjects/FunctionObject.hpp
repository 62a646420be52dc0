// Function objects: post-processing run during the simulation, selected in controlDict's
// `functions` dictionary as in OpenFOAM. Each writes under postProcessing/<name>/<startTime>/.
//   functions
//   {
//       front { type surgeFront; direction (1 0); origin (0 0); executeInterval 0.01; }
//   }
// executeInterval (simulated time, default 0: every step) is read by the driver.
#pragma once

#include "core/Registry.hpp"
#include "functionObjects/ErrorNorms.hpp"
#include "functionObjects/Reductions.hpp"
#include "functionObjects/TimeSeriesFile.hpp"
#include "io/Dictionary.hpp"
#include "physics/FluidSystemView.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sph {

template <int D>
struct FunctionObjectContext {
    std::filesystem::path caseDirectory;
    std::filesystem::path outputDirectory;  // postProcessing/<name>/<startTime>
    double rho0;
    FluidSystemView<D> system;  // the domain, gravity and models, for checks before the first step
    const Reductions& reductions = Reductions::oneProcess();
    // Has the system record a wall-force patch's load at each evaluation (Patch::load); empty
    // where no system evaluates the view's rates.
    std::function<void(std::size_t patch)> recordPatchLoad = {};

    // The object's time series, or one that writes nothing where this process does not write.
    TimeSeriesFile series(const std::string& file, const std::string& header) const {
        return reductions.writesFiles() ? TimeSeriesFile(outputDirectory, file, header) : TimeSeriesFile();
    }
};

template <int D>
class FunctionObject {
public:
    virtual ~FunctionObject() = default;
    virtual std::string describe() const = 0;
    virtual void execute(const FluidSystemView<D>& system, double t) = 0;
    // Errors against a reference the case declared, for the run's closing summary; none by default.
    virtual std::vector<ReportedError> errors() const { return {}; }
};

template <int D>
using FunctionObjectRegistry = Registry<std::unique_ptr<FunctionObject<D>>, const Dictionary&, const FunctionObjectContext<D>&>;

template <int D>
FunctionObjectRegistry<D> makeFunctionObjectRegistry();

}  // namespace sph
