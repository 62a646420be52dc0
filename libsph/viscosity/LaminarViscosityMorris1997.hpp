// Laminar viscosity of Morris, Fox & Zhu (1997), mu = rho nu:
//   dv_i/dt += sum_j m_j (mu_i + mu_j) / (rho_i rho_j) * (r_ij . grad_i W_ij) / (r^2 + 0.01 h^2) * v_ij
// Reference: J.P. Morris, P.J. Fox, Y. Zhu, J. Comput. Phys. 136 (1997) 214-226, Eq. (8).
// nu is the fluid's kinematic viscosity from constant/fluidProperties.
// Example (system/sphSchemes):   viscosity { type laminar; }
#pragma once

#include "core/Vector.hpp"

namespace sph {

struct LaminarViscosityMorris1997 {
    static constexpr bool enabled = true;

    explicit LaminarViscosityMorris1997(double nu) : nu(nu) {}

    // The acceleration of i from j is m_j pairFactor v_ij (j receives -m_i pairFactor v_ij), from
    // r^2, 1/(r^2 + 0.01 h^2) and F = (dW/dr)/r.
    static constexpr bool alongSeparation = false;
    double pairFactor(double /*vDotR*/, double r2, double inverseRegularisedR2, double rhoi, double rhoj, double F) const {
        return nu * (rhoi + rhoj) / (rhoi * rhoj) * F * r2 * inverseRegularisedR2;
    }

    double nu;
};

}  // namespace sph
