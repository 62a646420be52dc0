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

    LaminarViscosityMorris1997(double nu, double h) : nu(nu), eta2(0.01 * h * h) {}

    template <int D>
    Vec<D> acceleration(const Vec<D>& /*rij*/, const Vec<D>& vij, double r2, double rhoi, double rhoj, double mj, double F) const {
        return (mj * nu * (rhoi + rhoj) / (rhoi * rhoj) * F * r2 / (r2 + eta2)) * vij;
    }

    double nu, eta2;
};

}  // namespace sph
