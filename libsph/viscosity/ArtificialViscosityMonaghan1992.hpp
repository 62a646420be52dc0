// Artificial viscosity of Monaghan (1992), applied to approaching pairs only:
//   mu_ij = h v_ij.r_ij / (r^2 + 0.01 h^2)   (v_ij.r_ij < 0, else 0)
//   Pi_ij = (-alpha c0 mu_ij + beta mu_ij^2) / rho_bar,   rho_bar = (rho_i + rho_j)/2
//   dv_i/dt += - sum_j m_j Pi_ij grad_i W_ij
// Reference: J.J. Monaghan, Annu. Rev. Astron. Astrophys. 30 (1992) 543-574.
// Example (system/sphSchemes):   viscosity { type artificial; alpha 0.02; beta 0; }
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <string_view>

namespace sph {

struct ArtificialViscosityMonaghan1992 {
    static constexpr std::string_view name = "artificial";
    static ModelDoc documentation() {
        return {"Monaghan artificial viscosity on approaching pairs",
                "Monaghan, Annu. Rev. Astron. Astrophys. 30 (1992) 543",
                {{"alpha", "", "linear coefficient (0.01-0.1 for water)"}, {"beta", "0", "quadratic coefficient"}}};
    }
    static ArtificialViscosityMonaghan1992 create(const Dictionary& dict, const ModelContext& context) {
        return ArtificialViscosityMonaghan1992(dict.getNonNegative("alpha"), dict.getNonNegativeOrDefault("beta", 0.0), context.h, context.c0);
    }
    std::string describe() const { return fmt::format("artificial: alpha {:g}, beta {:g}", alpha, beta); }

    static constexpr bool enabled = true;

    ArtificialViscosityMonaghan1992(double alpha, double beta, double h, double c0) : alpha(alpha), beta(beta), h(h), c0(c0) {}

    // The acceleration of i from j is m_j pairFactor r_ij (j receives -m_i pairFactor r_ij), from
    // v_ij.r_ij, 1/(r^2 + 0.01 h^2) and F = (dW/dr)/r. Receding pairs get mu = 0 without a branch
    // (unpredictable in the pair loop, and in the way of its vectorisation).
    static constexpr bool alongSeparation = true;
    double pairFactor(double vDotR, double /*r2*/, double inverseRegularisedR2, double rhoi, double rhoj, double F) const {
        // The division does not wait for mu, so that its latency overlaps the rest of the pair.
        const double inverseMeanDensity = 2.0 / (rhoi + rhoj);
        const double mu = h * std::min(vDotR, 0.0) * inverseRegularisedR2;
        return (alpha * c0 * mu - beta * mu * mu) * inverseMeanDensity * F;
    }

    double alpha, beta, h, c0;
};

}  // namespace sph
