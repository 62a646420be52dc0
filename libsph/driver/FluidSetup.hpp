// Assembles a FluidSystem and its integrator from a case directory and a start time: reads
// the dictionaries, selects every model through its registry (echoing each selection with its
// coefficients) and validates the state before the first step.
#pragma once

#include "driver/CaseDirectory.hpp"
#include "io/ParticleFile.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <memory>
#include <vector>

namespace sph {

template <int D>
struct CaseSetup {
    std::unique_ptr<FluidSystem<D>> system;
    std::unique_ptr<TimeIntegrator<D>> integrator;
    std::string integratorType;  // its name in system/timeIntegration
    double rho0 = 0.0;
    double courant = 0.2;
    double maxDeltaT = 0.0;    // +inf when not given
    double fixedDeltaT = 0.0;  // 0: adaptive
    StateHeader header;
    std::vector<std::string> patchNames;
    std::vector<Dictionary> dictionaries;  // checked for unused keywords once everything is read
};

template <int D>
CaseSetup<D> setUpCase(const std::filesystem::path& caseDirectory, const TimeDirectory& start);

}  // namespace sph
