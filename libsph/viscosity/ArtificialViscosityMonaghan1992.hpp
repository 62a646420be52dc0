// Artificial viscosity of Monaghan (1992), applied to approaching pairs only:
//   mu_ij = h v_ij.r_ij / (r^2 + 0.01 h^2)   (v_ij.r_ij < 0, else 0)
//   Pi_ij = (-alpha c0 mu_ij + beta mu_ij^2) / rho_bar,   rho_bar = (rho_i + rho_j)/2
//   dv_i/dt += - sum_j m_j Pi_ij grad_i W_ij
// Reference: J.J. Monaghan, Annu. Rev. Astron. Astrophys. 30 (1992) 543-574.
// Example (system/sphSchemes):   viscosity { type artificial; alpha 0.02; beta 0; }
#pragma once

#include "core/Vector.hpp"

namespace sph {

struct ArtificialViscosityMonaghan1992 {
    static constexpr bool enabled = true;

    ArtificialViscosityMonaghan1992(double alpha, double beta, double h, double c0)
        : alpha(alpha), beta(beta), h(h), c0(c0), eta2(0.01 * h * h) {}

    // Acceleration of i from j; F = (dW/dr)/r, so grad_i W_ij = F r_ij.
    template <int D>
    Vec<D> acceleration(const Vec<D>& rij, const Vec<D>& vij, double r2, double rhoi, double rhoj, double mj, double F) const {
        const double vr = vij.dot(rij);
        if (vr >= 0.0) return Vec<D>::Zero();
        const double mu = h * vr / (r2 + eta2);
        const double pi = (-alpha * c0 * mu + beta * mu * mu) / (0.5 * (rhoi + rhoj));
        return (-mj * pi * F) * rij;
    }

    double alpha, beta, h, c0, eta2;
};

}  // namespace sph
