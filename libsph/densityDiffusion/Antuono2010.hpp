// delta-SPH density diffusion of Antuono, Colagrossi, Marrone & Molteni (2010), with the
// renormalised density gradient as in Marrone et al. (2011), fluid-fluid pairs:
//   D_i = delta h c0 sum_j psi_ij . grad_i W_ij V_j,   V_j = m_j / rho_j
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / (|x_j - x_i|^2 + 0.01 h^2) - (<grad rho>^L_i + <grad rho>^L_j)
//   <grad rho>^L_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,   L_i = [sum_j (x_j - x_i) (x) grad_i W_ij V_j]^-1
// The gradients remove the first-order part of the density differences, so a hydrostatic
// stratification is not diffused (Molteni & Colagrossi's term diffuses it near a free surface,
// where the sums are one-sided). Where L_i's matrix is near singular (det below 0.1, a particle
// with few neighbours: its matrix is the identity in full support) the gradient is taken
// without renormalisation. With grad_i W_ij = F r_ij, r_ij = x_i - x_j, a pair adds
//   toI = 2 delta h c0 F [(rho_i - rho_j) r^2 / (r^2 + 0.01 h^2) - (<grad rho>_i + <grad rho>_j) . r_ij / 2]
// times V_j to i's rate and -toI V_i to j's. The gradients cost one more pass over the pairs.
// References: M. Antuono, A. Colagrossi, S. Marrone, D. Molteni, Comput. Phys. Commun. 181 (2010)
// 532-549; S. Marrone, M. Antuono, A. Colagrossi, G. Colicchio, D. Le Touze, G. Graziani, Comput.
// Methods Appl. Mech. Engrg. 200 (2011) 1526-1542.
// Example (system/sphSchemes):   densityDiffusion { type antuono; delta 0.1; }
#pragma once

#include "densityDiffusion/DiffusionCoefficient.hpp"
#include "physics/ModelContext.hpp"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace sph {

struct Antuono2010 {
    static constexpr std::string_view name = "antuono";
    static ModelDoc documentation() {
        return {"delta-SPH diffusion with the renormalised density gradient (a hydrostatic gradient is not diffused)",
                "Antuono et al., Comput. Phys. Commun. 181 (2010) 532; Marrone et al., CMAME 200 (2011) 1526",
                {diffusionCoefficientDoc()}};
    }
    static Antuono2010 create(const Dictionary& dict, const ModelContext& context) {
        return Antuono2010(readDiffusionCoefficient(dict), context.h, context.c0);
    }
    std::string describe() const { return fmt::format("antuono: delta {:g}", delta); }

    static constexpr bool enabled = true;
    static constexpr bool renormalisedGradient = true;  // the pair loop computes <grad rho>^L first

    Antuono2010(double delta, double h, double c0) : delta(delta), coefficient(2.0 * delta * h * c0) {}

    // The pair (i, j) adds toI V_j to i's density rate and toJ V_i to j's, from r^2,
    // 1/(r^2 + 0.01 h^2), F = (dW/dr)/r and (<grad rho>_i + <grad rho>_j) . r_ij.
    void pairRates(double r2, double inverseRegularisedR2, double rhoi, double rhoj, double F, double gradientSumDotR, double& toI,
                   double& toJ) const {
        toI = coefficient * F * ((rhoi - rhoj) * r2 * inverseRegularisedR2 - 0.5 * gradientSumDotR);
        toJ = -toI;
    }

    double delta, coefficient;
};

// True for a diffusion whose pairs read the renormalised density gradient.
template <class Diffusion>
constexpr bool usesDensityGradient = requires {
    Diffusion::renormalisedGradient;
};

}  // namespace sph
