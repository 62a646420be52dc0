// Wendland C2 kernel (Wendland 1995), support radius 2h, s = r/(2h):
//   1D:     W = sigma (1-s)^3 (1+3s),  sigma = 5/(8h)
//   2D, 3D: W = sigma (1-s)^4 (1+4s),  sigma = 7/(4 pi h^2), 21/(16 pi h^3)
// Reference: H. Wendland, Adv. Comput. Math. 4 (1995) 389-396; normalisations as in
// W. Dehnen, H. Aly, MNRAS 425 (2012) 1068-1082.
// Example (system/sphSchemes):   kernel { type wendlandC2; hdx 1.4142; }
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace sph {

template <int D>
struct WendlandC2 {
    static constexpr std::string_view name = "wendlandC2";
    static constexpr std::string_view summary = "Wendland C2, support 2h";
    static constexpr std::string_view reference = "Wendland, Adv. Comput. Math. 4 (1995) 389";

    explicit WendlandC2(double smoothingLength) : h(smoothingLength), invH(1.0 / smoothingLength), sigma(normalisation(smoothingLength)) {}

    double supportRadius() const { return 2.0 * h; }

    double value(double r) const {
        const double s = 0.5 * r * invH;
        const double t = std::max(1.0 - s, 0.0);
        if constexpr (D == 1) return sigma * t * t * t * (1.0 + 3.0 * s);
        return sigma * (t * t) * (t * t) * (1.0 + 4.0 * s);
    }

    double gradientFactor(double r) const {
        const double t = std::max(1.0 - 0.5 * r * invH, 0.0);
        if constexpr (D == 1) return -3.0 * sigma * invH * invH * t * t;
        return -5.0 * sigma * invH * invH * t * t * t;
    }

    static double normalisation(double h) {
        if constexpr (D == 1) return 5.0 / (8.0 * h);
        if constexpr (D == 2) return 7.0 / (4.0 * std::numbers::pi * h * h);
        return 21.0 / (16.0 * std::numbers::pi * h * h * h);
    }

    double h, invH, sigma;
};

}  // namespace sph
