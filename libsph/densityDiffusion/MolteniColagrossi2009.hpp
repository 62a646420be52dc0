// Density diffusion of Molteni & Colagrossi (2009), fluid-fluid pairs, added to the continuity rate:
//   D_i = 2 delta h c0 sum_j (rho_j - rho_i) (r_ji . grad_i W_ij) / (r^2 + 0.01 h^2) m_j / rho_j
// (r_ji = x_j - x_i; with r_ij . grad W = F r^2 this is the expression in pairRates()).
// Reference: D. Molteni, A. Colagrossi, Comput. Phys. Commun. 180 (2009) 861-872.
// Example (system/sphSchemes):   densityDiffusion { type molteniColagrossi; delta 0.1; }
#pragma once

#include "densityDiffusion/DiffusionCoefficient.hpp"
#include "physics/ModelContext.hpp"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace sph {

struct MolteniColagrossi2009 {
    static constexpr std::string_view name = "molteniColagrossi";
    static ModelDoc documentation() {
        return {
            "delta-SPH diffusion of density differences", "Molteni & Colagrossi, Comput. Phys. Commun. 180 (2009) 861", {diffusionCoefficientDoc()}};
    }
    static MolteniColagrossi2009 create(const Dictionary& dict, const ModelContext& context) {
        return MolteniColagrossi2009(readDiffusionCoefficient(dict), context.h, context.c0);
    }
    std::string describe() const { return fmt::format("molteniColagrossi: delta {:g}", delta); }

    static constexpr bool enabled = true;

    MolteniColagrossi2009(double delta, double h, double c0) : delta(delta), coefficient(2.0 * delta * h * c0) {}

    // The pair (i, j) adds toI V_j to i's density rate and toJ V_i to j's, V = m / rho, from
    // r^2, 1/(r^2 + 0.01 h^2) and F = (dW/dr)/r (g.r_ij is for Fourtakas' hydrostatic part).
    void pairRates(double /*gravityDotR*/, double r2, double inverseRegularisedR2, double rhoi, double rhoj, double F, double& toI,
                   double& toJ) const {
        toI = coefficient * (rhoi - rhoj) * F * r2 * inverseRegularisedR2;
        toJ = -toI;
    }

    double delta, coefficient;
};

}  // namespace sph
