// The deficiency correction's default repulsion partner: a penalty on the distance to the
// wall surface, blended over the wall particles within the kernel support, so that a fluid
// particle sliding along a wall feels no bumps between wall particles (the discrete Lennard-
// Jones and Monaghan-Kajtar laws with wall spacing dx drag a dam-break front measurably:
// doc/boundaryFindings.md). For fluid particle i, over wall particles j with area A_j:
//   d_i = sum_j A_j W_ij (r_ij . n_j) / sum_j A_j W_ij     (the distance to the wall's tangent planes)
//   N_i = sum_j A_j W_ij n_j / |sum_j A_j W_ij n_j|
//   a_i += (K / dx) max(0, 1 - d_i / d0)^2 N_i
// zero beyond d0 (default dx/2, where the first fluid row starts), so fluid at rest on the wall
// feels nothing; K (a squared velocity, default c0^2/20) stops a particle arriving at up to
// sqrt(K/6) = 0.09 c0 within d0, above any speed a WCSPH flow is run at (|v| < c0/10).
// Example (constant/boundaryProperties, inside a deficiency-correction patch):
//   repulsion { type wallDistance; K 245; distance 0.005; }
#pragma once

#include "core/Vector.hpp"

#include <algorithm>

namespace sph {

struct WallDistancePenalty {
    double K;
    double dx;
    double distance;  // d0

    template <int D>
    Vec<D> acceleration(double areaWeight, const Vec<D>& normalSum, double distanceSum) const {
        if (!(areaWeight > 0.0) || !(normalSum.squaredNorm() > 0.0)) return Vec<D>::Zero();
        const double gap = std::max(0.0, 1.0 - distanceSum / areaWeight / distance);
        return (K / dx * gap * gap) * normalSum.normalized();
    }
};

}  // namespace sph
