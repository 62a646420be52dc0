// Density diffusion of Fourtakas et al. (2019): Molteni & Colagrossi's term acting on the
// dynamic density only, the hydrostatic part removed, fluid-fluid pairs:
//   D_i = 2 delta h c0 sum_j [(rho_j - rho_i) - rho^H_ji] (r_ji . grad_i W_ij) / (r^2 + 0.01 h^2) m_j / rho_j
//   rho^H_ji = rho0 [ (1 - rho0 g.r_ij / K)^(1/n) - 1 ],   r_ij = x_i - x_j
// with K, n the stiffness and exponent of the equation of state (Tait: B, gamma; linear: rho0 c0^2, 1)
// and g the gravity vector at the current time.
// Reference: G. Fourtakas, J.M. Dominguez, R. Vacondio, B.D. Rogers, Comput. Fluids 190 (2019) 346-361.
// Example (system/sphSchemes):   densityDiffusion { type fourtakas; delta 0.1; }
#pragma once

#include "core/Vector.hpp"

#include <cmath>

namespace sph {

template <int D>
struct Fourtakas2019 {
    static constexpr bool enabled = true;

    Fourtakas2019(double delta, double h, double c0, double rho0, double stiffness, double exponent)
        : delta(delta), coefficient(2.0 * delta * h * c0), eta2(0.01 * h * h), rho0(rho0),
          rho0OverStiffness(rho0 / stiffness), inverseExponent(1.0 / exponent), gravity(Vec<D>::Zero()) {}

    double rate(const Vec<D>& rij, double r2, double rhoi, double rhoj, double mj, double F) const {
        const double hydrostatic = rho0 * (std::pow(1.0 - rho0OverStiffness * gravity.dot(rij), inverseExponent) - 1.0);
        return coefficient * ((rhoi - rhoj) + hydrostatic) * F * r2 / (r2 + eta2) * mj / rhoj;
    }

    double delta, coefficient, eta2, rho0, rho0OverStiffness, inverseExponent;
    Vec<D> gravity;  // set before each evaluation (gravity may be ramped in time)
};

}  // namespace sph
