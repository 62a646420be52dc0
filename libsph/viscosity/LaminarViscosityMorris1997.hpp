// Laminar viscosity of Morris, Fox & Zhu (1997), mu = rho nu:
//   dv_i/dt += sum_j m_j (mu_i + mu_j) / (rho_i rho_j) * (r_ij . grad_i W_ij) / (r^2 + 0.01 h^2) * v_ij
// Reference: J.P. Morris, P.J. Fox, Y. Zhu, J. Comput. Phys. 136 (1997) 214-226, Eq. (8).
// nu is the fluid's kinematic viscosity from constant/fluidProperties.
// Example (system/sphSchemes):   viscosity { type laminar; }
#pragma once

#include "core/Registry.hpp"
#include "core/Vector.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace sph {

struct LaminarViscosityMorris1997 {
    static constexpr std::string_view name = "laminar";
    static ModelDoc documentation() {
        return {"Morris laminar viscosity, nu from constant/fluidProperties", "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214", {}};
    }
    static LaminarViscosityMorris1997 create(const Dictionary& dict, const ModelContext& context) {
        if (!(context.nu > 0.0)) dict.fail("type", "laminar viscosity needs a kinematic viscosity nu > 0 in constant/fluidProperties");
        return LaminarViscosityMorris1997(context.nu);
    }
    std::string describe() const { return fmt::format("laminar: nu {:g}", nu); }

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
