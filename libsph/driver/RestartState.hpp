// What a restart needs beyond the particle fields, carried in the state file's header: the
// time integrator's type and state (another integrator ignores it) and each free body's state.
#pragma once

#include "physics/FluidSystem.hpp"
#include "io/ParticleFile.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <map>
#include <string>
#include <vector>

namespace sph {

// Sets header.integrator and header.restart.
template <int D>
void collectRestartState(const FluidSystem<D>& system, const TimeIntegrator<D>& integrator, const std::string& integratorType, StateHeader& header);

// Hands the saved state back and evaluates the rates at the start state. An integrator that
// carries rates evaluated at a predicted state (leapfrog) gets back the written ones when it
// wrote the state. `source` names the state file for messages.
template <int D>
void restoreRestartState(FluidSystem<D>& system, TimeIntegrator<D>& integrator, const std::string& integratorType, const StateHeader& header,
                         double t, const std::string& source);

}  // namespace sph
