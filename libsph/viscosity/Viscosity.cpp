#include "viscosity/Viscosity.hpp"

namespace sph {

ViscosityRegistry makeViscosityRegistry() {
    ViscosityRegistry registry("viscosity");
    registerEach(registry);
    return registry;
}

double viscousTimeStepNu(const Viscosity& viscosity) {
    if (const auto* laminar = std::get_if<LaminarViscosityMorris1997>(&viscosity)) return laminar->nu;
    return 0.0;
}

}  // namespace sph
