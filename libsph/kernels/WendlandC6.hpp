// Wendland C6 kernel (Wendland 1995), support radius 2h, s = r/(2h):
//   1D:     W = sigma (1-s)^7 (1 + 7s + 19s^2 + 21s^3),  sigma = 55/(64h)
//   2D, 3D: W = sigma (1-s)^8 (1 + 8s + 25s^2 + 32s^3),  sigma = 39/(14 pi h^2), 1365/(512 pi h^3)
// The smoothest of the family: Dehnen & Aly show it resists pairing at the large neighbour
// counts (hdx 2 and above) that make the SPH sums converge.
// Reference: H. Wendland, Adv. Comput. Math. 4 (1995) 389-396; normalisations as in
// W. Dehnen, H. Aly, MNRAS 425 (2012) 1068-1082.
// Example (system/sphSchemes):   kernel { type wendlandC6; hdx 2; }
#pragma once

#include <algorithm>
#include <numbers>
#include <string_view>

namespace sph {

template <int D>
struct WendlandC6 {
    static constexpr std::string_view name = "wendlandC6";
    static constexpr std::string_view summary = "Wendland C6, support 2h";
    static constexpr std::string_view reference = "Wendland, Adv. Comput. Math. 4 (1995) 389";

    explicit WendlandC6(double smoothingLength) : h(smoothingLength), invH(1.0 / smoothingLength), sigma(normalisation(smoothingLength)) {}

    double supportRadius() const { return 2.0 * h; }

    double value(double r) const {
        const double s = 0.5 * r * invH;
        const double t = std::max(1.0 - s, 0.0);
        const double t2 = t * t, t4 = t2 * t2;
        if constexpr (D == 1) return sigma * t4 * t2 * t * (1.0 + s * (7.0 + s * (19.0 + 21.0 * s)));
        return sigma * t4 * t4 * (1.0 + s * (8.0 + s * (25.0 + 32.0 * s)));
    }

    // dW/dr / r: d/ds of the polynomials above is -6s (1-s)^6 (3 + 18s + 35s^2) in 1D and
    // -22s (1-s)^7 (1 + 7s + 16s^2) in 2D and 3D, and ds/dr / r = 1/(4h^2 s).
    double gradientFactor(double r) const {
        const double s = 0.5 * r * invH;
        const double t = std::max(1.0 - s, 0.0);
        const double t2 = t * t, t4 = t2 * t2;
        if constexpr (D == 1) return -1.5 * sigma * invH * invH * t4 * t2 * (3.0 + s * (18.0 + 35.0 * s));
        return -5.5 * sigma * invH * invH * t4 * t2 * t * (1.0 + s * (7.0 + 16.0 * s));
    }

    static double normalisation(double h) {
        if constexpr (D == 1) return 55.0 / (64.0 * h);
        if constexpr (D == 2) return 39.0 / (14.0 * std::numbers::pi * h * h);
        return 1365.0 / (512.0 * std::numbers::pi * h * h * h);
    }

    double h, invH, sigma;
};

}  // namespace sph
