// The viscosity family.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"
#include "viscosity/ArtificialViscosityMonaghan1992.hpp"
#include "viscosity/LaminarViscosityMorris1997.hpp"
#include "viscosity/NoViscosity.hpp"

#include <string>
#include <variant>

namespace sph {

using Viscosity = std::variant<NoViscosity, ArtificialViscosityMonaghan1992, LaminarViscosityMorris1997>;

using ViscosityRegistry = Registry<Viscosity, const Dictionary&, const ModelContext&>;

ViscosityRegistry makeViscosityRegistry();

std::string describe(const Viscosity& viscosity);

// Kinematic viscosity that limits the time step (0 for none).
double viscousTimeStepNu(const Viscosity& viscosity);

}  // namespace sph
