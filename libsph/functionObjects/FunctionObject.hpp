// Function objects: post-processing run during the simulation, selected in controlDict's
// `functions` dictionary as in OpenFOAM. Each writes under postProcessing/<name>/<startTime>/.
//   functions
//   {
//       front { type surgeFront; direction (1 0); origin (0 0); executeInterval 0.01; }
//   }
// executeInterval (simulated time, default 0: every step) is read by the driver.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace sph {

template <int D>
class FluidSystem;

struct FunctionObjectContext {
    std::filesystem::path outputDirectory;  // postProcessing/<name>/<startTime>
    double rho0;
};

template <int D>
class FunctionObject {
public:
    virtual ~FunctionObject() = default;
    virtual std::string describe() const = 0;
    virtual void execute(const FluidSystem<D>& system, double t) = 0;
    // A closing line for the run log (an error figure, say); empty for none.
    virtual std::string summary() const { return {}; }
};

template <int D>
using FunctionObjectRegistry = Registry<std::unique_ptr<FunctionObject<D>>, const Dictionary&, const FunctionObjectContext&>;

template <int D>
FunctionObjectRegistry<D> makeFunctionObjectRegistry();

}  // namespace sph
