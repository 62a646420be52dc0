#include "equationsOfState/EquationOfState.hpp"

#include <fmt/format.h>

namespace sph {

EquationOfStateRegistry makeEquationOfStateRegistry() {
    const CoefficientDoc p0{"backgroundPressure", "0", "p0 added to the pressure [Pa]"};
    // Every equation of state needs the speed of sound, given or derived (physics/FluidProperties).
    const CoefficientDoc c0{"c0", "", "speed of sound [m/s] (this or c0FromHeight)"};
    const CoefficientDoc c0FromHeight{"c0FromHeight", "", "{ coefficient 10; height H; }: c0 = coefficient sqrt(|g| H) (this or c0)"};
    EquationOfStateRegistry registry("equationOfState");
    registry.add("tait",
                 {"p = B((rho/rho0)^gamma - 1) + p0, B = c0^2 rho0/gamma",
                  "Monaghan, J. Comput. Phys. 110 (1994) 399",
                  {c0, c0FromHeight, {"gamma", "7", "exponent"}, p0}},
                 [](const Dictionary& dict, double rho0, double c0) {
                     return EquationOfState{
                         TaitEquationOfState(rho0, c0, dict.getPositiveOrDefault("gamma", 7.0), dict.getOrDefault("backgroundPressure", 0.0))};
                 });
    registry.add("linear", {"p = c0^2 (rho - rho0) + p0", "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214", {c0, c0FromHeight, p0}},
                 [](const Dictionary& dict, double rho0, double c0) {
                     return EquationOfState{LinearEquationOfState(rho0, c0, dict.getOrDefault("backgroundPressure", 0.0))};
                 });
    return registry;
}

std::string describe(const EquationOfState& eos) {
    return std::visit(
        [](const auto& e) {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, TaitEquationOfState>)
                return fmt::format("tait: rho0 {:g}, c0 {:g}, gamma {:g}, B {:g}, backgroundPressure {:g}", e.rho0, e.c0, e.gamma, e.B, e.p0);
            else
                return fmt::format("linear: rho0 {:g}, c0 {:g}, backgroundPressure {:g}", e.rho0, e.c0, e.p0);
        },
        eos);
}

}  // namespace sph
