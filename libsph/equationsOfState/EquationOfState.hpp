// The equation-of-state family. The speed of sound c0 is resolved by the fluid properties
// (given, or derived from a reference height) and passed to the factory with rho0.
#pragma once

#include "core/Registry.hpp"
#include "equationsOfState/LinearEquationOfState.hpp"
#include "equationsOfState/TaitEquationOfState.hpp"
#include "io/Dictionary.hpp"

#include <variant>

namespace sph {

using EquationOfState = std::variant<TaitEquationOfState, LinearEquationOfState>;

// Factory arguments: the model's dictionary, rho0, c0.
using EquationOfStateRegistry = Registry<EquationOfState, const Dictionary&, double, double>;

EquationOfStateRegistry makeEquationOfStateRegistry();

// "Selecting equationOfState tait: gamma 7, B 1.2e5, ..." for the run log.
std::string describe(const EquationOfState& eos);

}  // namespace sph
