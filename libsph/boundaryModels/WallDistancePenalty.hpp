// The deficiency correction's default repulsion partner: a penalty on the distance to the
// wall particles' tangent planes, blended over the wall particles within the kernel support,
// so that a fluid particle sliding along a wall feels no bumps between wall particles (the
// discrete Lennard-Jones and Monaghan-Kajtar laws with wall spacing dx drag a dam-break front
// measurably: doc/boundaryFindings.md). For fluid particle i, over wall particles j of area A_j:
//   a_i += sum_j A_j W_ij [s_ij^2 K/dx + g_ij^2 zeta (c0/d0) max(0, -(v_i - v_j) . n_j)] n_j / sum_j A_j W_ij
//   g_ij = max(0, 1 - (r_ij . n_j) / d0),   s_ij = max(0, 1 - (r_ij . n_j) / d_s),   d_s <= d0
// zero beyond d0 (default dx/2, where the first fluid row starts), so fluid at rest on the wall
// feels nothing. The damper zeta stops particles closing on the wall without storing energy.
// The spring K (a squared velocity; default 0) holds what the correction does not: a slow creep
// through a one-layer floor, which the damper, resisting speed only, lets through. Acting within
// d_s = dx/4 (`springDistance`, default d0) it leaves the water at rest untouched; it still
// rings at impacts (the dam break's wall pressure noise, doc/boundaryFindings.md).
// Example (constant/boundaryProperties, inside a deficiency-correction patch):
//   repulsion { type wallDistance; K 1.5; damping 1; distance 0.025; springDistance 0.0125; }
#pragma once

#include "core/Vector.hpp"

#include <algorithm>

namespace sph {

struct WallDistancePenalty {
    double K;
    double dx;
    double distance;  // d0
    double zeta;      // the damper's coefficient
    double c0;
    double springDistance;  // d_s <= d0: where the spring starts

    // One wall particle's term, times A_j W_ij: rDotN = r_ij . n_j, closingSpeed = -(v_i - v_j) . n_j.
    double term(double rDotN, double closingSpeed) const {
        const double gap = std::max(0.0, 1.0 - rDotN / distance);
        const double springGap = std::max(0.0, 1.0 - rDotN / springDistance);
        return gap * gap * (zeta * c0 / distance * std::max(0.0, closingSpeed)) + springGap * springGap * K / dx;
    }
};

}  // namespace sph
