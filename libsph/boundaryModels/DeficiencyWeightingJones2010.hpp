// The published weighting of the deficiency correction (Jones, Yang & McCue-Weil 2010, Eq. 8):
//   w_ij = A^2 + (G^2 + 1/2) D,   A = s_j/|r_ij| (activation), G = (r_ij/|r_ij|) . n_j
//   (glancing), D = 1 - |r_ij|/r_inf (distance); blended with w_ij / sum_k w_ik.
#pragma once

#include "core/Vector.hpp"

namespace sph {

struct DeficiencyWeightingJones2010 {
    static constexpr bool normalised = true;

    template <int D>
    static double weight(double distance, const Vec<D>& direction, const Vec<D>& normal, double spacing, double /*area*/, double influenceRadius) {
        const double activation = spacing / distance;
        const double glancing = direction.dot(normal);
        return activation * activation + (glancing * glancing + 0.5) * (1.0 - distance / influenceRadius);
    }
};

}  // namespace sph
