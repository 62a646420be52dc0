// Density diffusion of Fourtakas et al. (2019): Molteni & Colagrossi's term acting on the
// dynamic density only, the hydrostatic part removed, fluid-fluid pairs:
//   D_i = 2 delta h c0 sum_j [(rho_j - rho_i) - rho^H_ji] (r_ji . grad_i W_ij) / (r^2 + 0.01 h^2) m_j / rho_j
//   rho^H_ji = rho0 [ (1 + y_ij)^(1/n) - 1 ],   y_ij = -rho0 g.r_ij / K,   r_ij = x_i - x_j
// with K, n the stiffness and exponent of the equation of state (Tait: B, gamma; linear: rho0 c0^2, 1)
// and g the gravity vector at the current time.
// |y| is at most n |g| r_max / K * rho0 (r_max the support radius): below 0.02 wherever
// c0^2 > 50 n g r_max (c0 > 10 m/s at h = 3 cm), and there the binomial series to y^8 equals
// the power to round-off (the next term is below 1e-15 of the first) at a fraction of the cost
// of std::pow. setGravity checks the bound once per evaluation; beyond it the pair loop runs
// beyondSeries(), the same model with std::pow.
// Reference: G. Fourtakas, J.M. Dominguez, R. Vacondio, B.D. Rogers, Comput. Fluids 190 (2019) 346-361.
// Example (system/sphSchemes):   densityDiffusion { type fourtakas; delta 0.1; }
#pragma once

#include "core/Vector.hpp"
#include "densityDiffusion/DiffusionCoefficient.hpp"
#include "physics/ModelContext.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>
#include <string_view>

namespace sph {

// Series: the hydrostatic part from the series; false: from std::pow (see beyondSeries()).
template <int D, bool Series = true>
struct Fourtakas2019 {
    static constexpr std::string_view name = "fourtakas";
    static ModelDoc documentation() {
        return {"diffusion of the dynamic density (hydrostatic part removed)",
                "Fourtakas et al., Comput. Fluids 190 (2019) 346",
                {diffusionCoefficientDoc()}};
    }
    static Fourtakas2019 create(const Dictionary& dict, const ModelContext& context) {
        return Fourtakas2019(readDiffusionCoefficient(dict), context.h, context.c0, context.rho0, context.stiffness, context.exponent);
    }
    std::string describe() const { return fmt::format("fourtakas: delta {:g}", delta); }

    static constexpr bool enabled = true;
    static constexpr double seriesLimit = 0.02;
    static constexpr int seriesTerms = 8;

    Fourtakas2019(double delta, double h, double c0, double rho0, double stiffness, double exponent)
        : delta(delta), coefficient(2.0 * delta * h * c0), rho0(rho0), rho0OverStiffness(rho0 / stiffness), inverseExponent(1.0 / exponent) {
        // Binomial coefficients of (1 + y)^a - 1, a = 1/n, times rho0.
        double c = rho0;
        for (int k = 0; k < seriesTerms; ++k) {
            c *= (inverseExponent - k) / (k + 1);
            series[static_cast<std::size_t>(k)] = c;
        }
    }

    template <bool OtherSeries>
    explicit Fourtakas2019(const Fourtakas2019<D, OtherSeries>& other)
        : delta(other.delta),
          coefficient(other.coefficient),
          rho0(other.rho0),
          rho0OverStiffness(other.rho0OverStiffness),
          inverseExponent(other.inverseExponent),
          series(other.series),
          seriesHolds(other.seriesHolds) {}

    // The same model with the hydrostatic part from std::pow, for the pair loop where setGravity
    // found the series out of reach: a loop in vector lanes cannot branch to std::pow per pair.
    Fourtakas2019<D, false> beyondSeries() const { return Fourtakas2019<D, false>(*this); }

    // Before each evaluation (gravity may be ramped in time); pairs are at most maxSeparation apart.
    void setGravity(const Vec<D>& g, double maxSeparation) { seriesHolds = rho0OverStiffness * g.norm() * maxSeparation < seriesLimit; }

    // rho0 [(1 + y)^(1/n) - 1] at y and at -y, as a pair needs both.
    void hydrostaticDensities(double y, double& atY, double& atMinusY) const {
        if constexpr (!Series) {
            atY = rho0 * (std::pow(1.0 + y, inverseExponent) - 1.0);
            atMinusY = rho0 * (std::pow(1.0 - y, inverseExponent) - 1.0);
        } else {
            // The odd terms y P(y^2) change sign with y, the even y^2 Q(y^2) do not.
            static_assert(seriesTerms % 2 == 0);
            const double y2 = y * y;
            double odd = series[seriesTerms - 2], even = series[seriesTerms - 1];
#pragma GCC unroll 8  // an inner loop left rolled would keep the pair loop from vectorising
            for (std::size_t k = seriesTerms - 2; k >= 2; k -= 2) {
                odd = series[k - 2] + y2 * odd;
                even = series[k - 1] + y2 * even;
            }
            odd *= y;
            even *= y2;
            atY = even + odd;
            atMinusY = even - odd;
        }
    }

    // The pair (i, j) adds toI V_j to i's density rate and toJ V_i to j's, V = m / rho, from
    // g.r_ij, r^2, 1/(r^2 + 0.01 h^2) and F = (dW/dr)/r. Plain numbers in and out, so a loop
    // over pairs keeps them in vector registers.
    void pairRates(double gravityDotR, double r2, double inverseRegularisedR2, double rhoi, double rhoj, double F, double& toI, double& toJ) const {
        const double y = -rho0OverStiffness * gravityDotR;
        const double common = coefficient * F * r2 * inverseRegularisedR2;
        double up, down;
        hydrostaticDensities(y, up, down);
        toI = common * ((rhoi - rhoj) + up);
        toJ = common * ((rhoj - rhoi) + down);
    }

    double delta, coefficient, rho0, rho0OverStiffness, inverseExponent;
    std::array<double, seriesTerms> series{};
    bool seriesHolds = true;
};

}  // namespace sph
