// Cubic B-spline kernel of Monaghan & Lattanzio (1985), support radius 2h.
//   q = r/h,  W = sigma (1 - 3/2 q^2 + 3/4 q^3)  for 0 <= q < 1
//             W = sigma/4 (2 - q)^3              for 1 <= q < 2,  0 beyond
//   sigma = 2/(3h) in 1D, 10/(7 pi h^2) in 2D, 1/(pi h^3) in 3D.
// Reference: J.J. Monaghan, J.C. Lattanzio, A&A 149 (1985) 135-143.
// Example (system/sphSchemes):   kernel { type cubicSpline; hdx 1.3; }
#pragma once

#include <numbers>
#include <string_view>

namespace sph {

template <int D>
struct CubicSplineMonaghanLattanzio1985 {
    static constexpr std::string_view name = "cubicSpline";
    static constexpr std::string_view summary = "cubic B-spline, support 2h";
    static constexpr std::string_view reference = "Monaghan & Lattanzio, A&A 149 (1985) 135";

    explicit CubicSplineMonaghanLattanzio1985(double smoothingLength)
        : h(smoothingLength), invH(1.0 / smoothingLength), sigma(normalisation(smoothingLength)) {}

    double supportRadius() const { return 2.0 * h; }

    double value(double r) const {
        const double q = r * invH;
        if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
        if (q < 2.0) return 0.25 * sigma * (2.0 - q) * (2.0 - q) * (2.0 - q);
        return 0.0;
    }

    // (dW/dr)/r, so that grad W = gradientFactor(r) * r_vec; finite at r = 0.
    // Both pieces evaluated and one selected: no branch, so a loop over pairs vectorises.
    double gradientFactor(double r) const {
        const double q = r * invH;
        const double outer = std::max(2.0 - q, 0.0);
        const double piece = q < 1.0 ? -3.0 + 2.25 * q : -0.75 * outer * outer / std::max(q, 1.0);
        return sigma * invH * invH * piece;
    }

    static double normalisation(double h) {
        if constexpr (D == 1) return 2.0 / (3.0 * h);
        if constexpr (D == 2) return 10.0 / (7.0 * std::numbers::pi * h * h);
        return 1.0 / (std::numbers::pi * h * h * h);
    }

    double h, invH, sigma;
};

}  // namespace sph
