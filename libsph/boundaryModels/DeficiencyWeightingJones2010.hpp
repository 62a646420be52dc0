// The published weighting of the deficiency correction (Jones, Yang & McCue-Weil 2010, Eq. 8):
//   w_ij = A^2 + (G^2 + 1/2) D,   A = s_j/|r_ij| (activation), G = (r_ij/|r_ij|) . n_j
//   (glancing), D = 1 - |r_ij|/r_inf (distance); blended with w_ij / sum_k w_ik.
// In 3D a wall particle with no area (boxWalls' edges and corners, where the faces' particles
// tile the faces) takes no weight: a row of edge particles as dense as a face's row pulled the
// blend along the diagonal (hydrostaticTank3D, H/dx = 10: near-floor pressure RMS 6.7 % and 4
// particles through the floor with it, 1.9 % and none without). In 2D a corner is one particle
// and keeps its weight (leaving it out moved the dam break's P3 error from 0.231 to 0.276).
#pragma once

#include "core/Vector.hpp"

namespace sph {

struct DeficiencyWeightingJones2010 {
    static constexpr bool normalised = true;

    template <int D>
    static double weight(double distance, const Vec<D>& direction, const Vec<D>& normal, double spacing, double area, double influenceRadius) {
        if constexpr (D == 3)
            if (area == 0.0) return 0.0;
        const double activation = spacing / distance;
        const double glancing = direction.dot(normal);
        return activation * activation + (glancing * glancing + 0.5) * (1.0 - distance / influenceRadius);
    }
};

}  // namespace sph
