// Tait equation of state (Cole 1948, as used for WCSPH by Monaghan 1994):
//   p = B ((rho/rho0)^gamma - 1) + p0,   B = c0^2 rho0 / gamma
// A whole gamma (7, the usual one) is raised by repeated squaring: a few multiplications where
// std::pow costs a hundred cycles, equal to it within a few units in the last place.
// Reference: J.J. Monaghan, J. Comput. Phys. 110 (1994) 399-406; Batchelor (1967).
// Example (constant/fluidProperties):
//   equationOfState { type tait; gamma 7; c0 20; backgroundPressure 0; }
#pragma once

#include "equationsOfState/SpeedOfSoundKeywords.hpp"
#include "io/Dictionary.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <string_view>

namespace sph {

struct TaitEquationOfState {
    static constexpr std::string_view name = "tait";
    static ModelDoc documentation() {
        return {"p = B((rho/rho0)^gamma - 1) + p0, B = c0^2 rho0/gamma", "Monaghan, J. Comput. Phys. 110 (1994) 399",
                withSpeedOfSound({{"gamma", "7", "exponent"}})};
    }
    static TaitEquationOfState create(const Dictionary& dict, double rho0, double c0) {
        return TaitEquationOfState(rho0, c0, dict.getPositiveOrDefault("gamma", 7.0), dict.getOrDefault("backgroundPressure", 0.0));
    }
    std::string describe() const {
        return fmt::format("tait: rho0 {:g}, c0 {:g}, gamma {:g}, B {:g}, backgroundPressure {:g}", rho0, c0, gamma, B, p0);
    }

    TaitEquationOfState(double rho0, double c0, double gamma, double p0)
        : rho0(rho0),
          c0(c0),
          gamma(gamma),
          p0(p0),
          B(c0 * c0 * rho0 / gamma),
          wholeGamma(gamma == std::floor(gamma) && gamma <= 64.0 ? static_cast<int>(gamma) : 0) {}

    double pressure(double rho) const {
        const double ratio = rho / rho0;
        return B * ((wholeGamma > 0 ? wholePower(ratio, wholeGamma) : std::pow(ratio, gamma)) - 1.0) + p0;
    }
    // At p0 (a wall clamped there, or with no fluid near) exactly rho0, which std::pow gives too,
    // without its hundred cycles.
    double density(double p) const { return p == p0 ? rho0 : rho0 * std::pow((p - p0) / B + 1.0, 1.0 / gamma); }
    // The stiffness and exponent of p - p0 = K ((rho/rho0)^n - 1), for hydrostatic corrections.
    double stiffness() const { return B; }
    double exponent() const { return gamma; }

    double rho0, c0, gamma, p0, B;
    int wholeGamma;  // gamma when it is a whole number up to 64, else 0

private:
    static double wholePower(double x, int n) {
        double result = 1.0;
        for (; n > 0; n >>= 1, x *= x)
            if (n & 1) result *= x;
        return result;
    }
};

}  // namespace sph
