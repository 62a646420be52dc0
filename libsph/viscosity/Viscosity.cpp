#include "viscosity/Viscosity.hpp"

#include <fmt/format.h>

namespace sph {

ViscosityRegistry makeViscosityRegistry() {
    ViscosityRegistry registry("viscosity");
    registry.add("none", {"inviscid", "", {}}, [](const Dictionary&, const ModelContext&) { return Viscosity{NoViscosity{}}; });
    registry.add(
        "artificial",
        {"Monaghan artificial viscosity on approaching pairs",
         "Monaghan, Annu. Rev. Astron. Astrophys. 30 (1992) 543",
         {{"alpha", "", "linear coefficient (0.01-0.1 for water)"}, {"beta", "0", "quadratic coefficient"}}},
        [](const Dictionary& dict, const ModelContext& c) {
            return Viscosity{ArtificialViscosityMonaghan1992(dict.getNonNegative("alpha"), dict.getNonNegativeOrDefault("beta", 0.0), c.h, c.c0)};
        });
    registry.add("laminar", {"Morris laminar viscosity, nu from constant/fluidProperties", "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214", {}},
                 [](const Dictionary& dict, const ModelContext& c) {
                     if (!(c.nu > 0.0)) dict.fail("type", "laminar viscosity needs a kinematic viscosity nu > 0 in constant/fluidProperties");
                     return Viscosity{LaminarViscosityMorris1997(c.nu)};
                 });
    return registry;
}

std::string describe(const Viscosity& viscosity) {
    return std::visit(
        [](const auto& v) -> std::string {
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, NoViscosity>)
                return "none";
            else if constexpr (std::is_same_v<V, ArtificialViscosityMonaghan1992>)
                return fmt::format("artificial: alpha {:g}, beta {:g}", v.alpha, v.beta);
            else
                return fmt::format("laminar: nu {:g}", v.nu);
        },
        viscosity);
}

double viscousTimeStepNu(const Viscosity& viscosity) {
    if (const auto* laminar = std::get_if<LaminarViscosityMorris1997>(&viscosity)) return laminar->nu;
    return 0.0;
}

}  // namespace sph
