// The viscosity family: each model declares itself in its header (name, documentation,
// factory, run-log line) and is one entry in the variant below.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"
#include "viscosity/ArtificialViscosityMonaghan1992.hpp"
#include "viscosity/LaminarViscosityMorris1997.hpp"
#include "viscosity/NoViscosity.hpp"

#include <concepts>
#include <string>
#include <variant>

namespace sph {

using Viscosity = std::variant<NoViscosity, ArtificialViscosityMonaghan1992, LaminarViscosityMorris1997>;

// What the pair loop asks of a viscosity: whether it has a term at all (a case without one
// compiles none), and if so the pair factor, along r_ij or along v_ij.
template <class V>
concept ViscosityModel = requires {
    { V::enabled } -> std::convertible_to<bool>;
}
&&(!V::enabled || requires(const V viscosity, double value) {
    { V::alongSeparation } -> std::convertible_to<bool>;
    { viscosity.pairFactor(value, value, value, value, value, value) } -> std::same_as<double>;
});
template <class Family>
inline constexpr bool allViscosities = false;
template <class... Models>
inline constexpr bool allViscosities<std::variant<Models...>> = (ViscosityModel<Models> && ...);
static_assert(allViscosities<Viscosity>);

using ViscosityRegistry = Registry<Viscosity, const Dictionary&, const ModelContext&>;

ViscosityRegistry makeViscosityRegistry();

inline std::string describe(const Viscosity& viscosity) { return describeModel(viscosity); }

// Kinematic viscosity that limits the time step (0 for none).
double viscousTimeStepNu(const Viscosity& viscosity);

}  // namespace sph
