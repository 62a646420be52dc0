// Linear (isothermal) equation of state:  p = c0^2 (rho - rho0) + p0
// Reference: J.P. Morris, P.J. Fox, Y. Zhu, J. Comput. Phys. 136 (1997) 214-226.
// Example (constant/fluidProperties):
//   equationOfState { type linear; c0 10; backgroundPressure 0; }
#pragma once

#include "equationsOfState/SpeedOfSoundKeywords.hpp"
#include "io/Dictionary.hpp"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace sph {

struct LinearEquationOfState {
    static constexpr std::string_view name = "linear";
    static ModelDoc documentation() {
        return {"p = c0^2 (rho - rho0) + p0", "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214", withSpeedOfSound({})};
    }
    static LinearEquationOfState create(const Dictionary& dict, double rho0, double c0) {
        return LinearEquationOfState(rho0, c0, dict.getOrDefault("backgroundPressure", 0.0));
    }
    std::string describe() const { return fmt::format("linear: rho0 {:g}, c0 {:g}, backgroundPressure {:g}", rho0, c0, p0); }

    LinearEquationOfState(double rho0, double c0, double p0) : rho0(rho0), c0(c0), p0(p0) {}

    double pressure(double rho) const { return c0 * c0 * (rho - rho0) + p0; }
    double density(double p) const { return rho0 + (p - p0) / (c0 * c0); }
    double stiffness() const { return c0 * c0 * rho0; }
    double exponent() const { return 1.0; }

    double rho0, c0, p0;
};

}  // namespace sph
