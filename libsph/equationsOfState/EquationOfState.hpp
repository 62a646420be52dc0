// The equation-of-state family: each model declares itself in its header (name, documentation,
// factory, run-log line) and is one entry in the variant below. The speed of sound c0 is
// resolved by the fluid properties (given, or derived from a reference height) and passed to the
// factory with rho0.
#pragma once

#include "core/Registry.hpp"
#include "equationsOfState/LinearEquationOfState.hpp"
#include "equationsOfState/TaitEquationOfState.hpp"
#include "io/Dictionary.hpp"

#include <concepts>
#include <variant>

namespace sph {

using EquationOfState = std::variant<TaitEquationOfState, LinearEquationOfState>;

// What the solver asks of an equation of state: p(rho) and its inverse, and the stiffness K and
// exponent n of p - p0 = K ((rho/rho0)^n - 1) for the hydrostatic corrections.
template <class E>
concept EquationOfStateModel = requires(const E eos, double value) {
    { eos.pressure(value) } -> std::same_as<double>;
    { eos.density(value) } -> std::same_as<double>;
    { eos.stiffness() } -> std::same_as<double>;
    { eos.exponent() } -> std::same_as<double>;
    { eos.rho0 } -> std::convertible_to<double>;
    { eos.c0 } -> std::convertible_to<double>;
    { eos.p0 } -> std::convertible_to<double>;
};
template <class Family>
inline constexpr bool allEquationsOfState = false;
template <class... Models>
inline constexpr bool allEquationsOfState<std::variant<Models...>> = (EquationOfStateModel<Models> && ...);
static_assert(allEquationsOfState<EquationOfState>);

// Factory arguments: the model's dictionary, rho0, c0.
using EquationOfStateRegistry = Registry<EquationOfState, const Dictionary&, double, double>;

EquationOfStateRegistry makeEquationOfStateRegistry();

// "tait: rho0 1000, c0 20, gamma 7, ..." for the run log.
inline std::string describe(const EquationOfState& eos) { return describeModel(eos); }

}  // namespace sph
