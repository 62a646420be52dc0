// Quintic spline kernel (Morris, Fox & Zhu 1997), support radius 3h.
//   q = r/h,  W = sigma [ (3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5 ], each bracket only where positive
//   sigma = 1/(120 h) in 1D, 7/(478 pi h^2) in 2D, 1/(120 pi h^3) in 3D.
// Reference: J.P. Morris, P.J. Fox, Y. Zhu, J. Comput. Phys. 136 (1997) 214-226.
// Example (system/sphSchemes):   kernel { type quinticSpline; hdx 1.0; }
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace sph {

template <int D>
struct QuinticSplineMorris1997 {
    static constexpr std::string_view name = "quinticSpline";
    static constexpr std::string_view summary = "quintic spline, support 3h";
    static constexpr std::string_view reference = "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214";

    explicit QuinticSplineMorris1997(double smoothingLength)
        : h(smoothingLength), invH(1.0 / smoothingLength), sigma(normalisation(smoothingLength)) {}

    double supportRadius() const { return 3.0 * h; }

    double value(double r) const {
        const double q = r * invH;
        const double a = std::max(3.0 - q, 0.0), b = std::max(2.0 - q, 0.0), c = std::max(1.0 - q, 0.0);
        return sigma * (pow5(a) - 6.0 * pow5(b) + 15.0 * pow5(c));
    }

    // (dW/dr)/r; the bracket vanishes like q at q = 0, so the small-q clamp loses nothing.
    double gradientFactor(double r) const {
        const double q = std::max(r * invH, 1e-12);
        const double a = std::max(3.0 - q, 0.0), b = std::max(2.0 - q, 0.0), c = std::max(1.0 - q, 0.0);
        return sigma * invH * invH * (-5.0 * pow4(a) + 30.0 * pow4(b) - 75.0 * pow4(c)) / q;
    }

    static double normalisation(double h) {
        if constexpr (D == 1) return 1.0 / (120.0 * h);
        if constexpr (D == 2) return 7.0 / (478.0 * std::numbers::pi * h * h);
        return 1.0 / (120.0 * std::numbers::pi * h * h * h);
    }

    double h, invH, sigma;

private:
    static double pow4(double x) { return (x * x) * (x * x); }
    static double pow5(double x) { return pow4(x) * x; }
};

}  // namespace sph
