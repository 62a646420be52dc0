// Density diffusion of Molteni & Colagrossi (2009), fluid-fluid pairs, added to the continuity rate:
//   D_i = 2 delta h c0 sum_j (rho_j - rho_i) (r_ji . grad_i W_ij) / (r^2 + 0.01 h^2) m_j / rho_j
// (r_ji = x_j - x_i; with r_ij . grad W = F r^2 this is the expression in rate()).
// Reference: D. Molteni, A. Colagrossi, Comput. Phys. Commun. 180 (2009) 861-872.
// Example (system/sphSchemes):   densityDiffusion { type molteniColagrossi; delta 0.1; }
#pragma once

#include "core/Vector.hpp"

namespace sph {

struct MolteniColagrossi2009 {
    static constexpr bool enabled = true;

    MolteniColagrossi2009(double delta, double h, double c0) : delta(delta), coefficient(2.0 * delta * h * c0), eta2(0.01 * h * h) {}

    template <int D>
    double rate(const Vec<D>& /*rij*/, double r2, double rhoi, double rhoj, double mj, double F) const {
        return coefficient * (rhoi - rhoj) * F * r2 / (r2 + eta2) * mj / rhoj;
    }

    double delta, coefficient, eta2;
};

}  // namespace sph
