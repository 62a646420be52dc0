// Wendland C4 kernel (Wendland 1995), support radius 2h, s = r/(2h):
//   1D:     W = sigma (1-s)^5 (1 + 5s + 8s^2),      sigma = 3/(4h)
//   2D, 3D: W = sigma (1-s)^6 (1 + 6s + 35/3 s^2),  sigma = 9/(4 pi h^2), 495/(256 pi h^3)
// Reference: H. Wendland, Adv. Comput. Math. 4 (1995) 389-396; normalisations as in
// W. Dehnen, H. Aly, MNRAS 425 (2012) 1068-1082.
// Example (system/sphSchemes):   kernel { type wendlandC4; hdx 1.6; }
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace sph {

template <int D>
struct WendlandC4 {
    static constexpr std::string_view name = "wendlandC4";
    static constexpr std::string_view summary = "Wendland C4, support 2h";
    static constexpr std::string_view reference = "Wendland, Adv. Comput. Math. 4 (1995) 389";

    explicit WendlandC4(double smoothingLength) : h(smoothingLength), invH(1.0 / smoothingLength), sigma(normalisation(smoothingLength)) {}

    double supportRadius() const { return 2.0 * h; }

    double value(double r) const {
        const double s = 0.5 * r * invH;
        const double t = std::max(1.0 - s, 0.0);
        const double t2 = t * t;
        if constexpr (D == 1) return sigma * t2 * t2 * t * (1.0 + 5.0 * s + 8.0 * s * s);
        return sigma * t2 * t2 * t2 * (1.0 + 6.0 * s + 35.0 / 3.0 * s * s);
    }

    double gradientFactor(double r) const {
        const double s = 0.5 * r * invH;
        const double t = std::max(1.0 - s, 0.0);
        const double t2 = t * t;
        if constexpr (D == 1) return -3.5 * sigma * invH * invH * t2 * t2 * (1.0 + 4.0 * s);
        return -14.0 / 3.0 * sigma * invH * invH * t2 * t2 * t * (1.0 + 5.0 * s);
    }

    static double normalisation(double h) {
        if constexpr (D == 1) return 3.0 / (4.0 * h);
        if constexpr (D == 2) return 9.0 / (4.0 * std::numbers::pi * h * h);
        return 495.0 / (256.0 * std::numbers::pi * h * h * h);
    }

    double h, invH, sigma;
};

}  // namespace sph
