// A refined weighting of the deficiency correction, from the divergence theorem: the
// uniform-pressure deficiency of particle i is -(2p/rho) sum_j W_ij S_j, with S_j = A_j n_j the
// wall particle's area vector (A_j the wall field `area`: the length of wall it stands for in
// 2D, its area in 3D; s_j^(D-1) where a state has no area field). The
// correction applies -sum_j C_j W_ij A_j n_j unnormalised, so a corner, where the two faces'
// area vectors add, and a curved wall, whose particles' areas differ, are weighted by the
// geometry itself rather than by the empirical w_ij (METHOD.md, "open improvements";
// compare Kulasegaram et al. 2004 and Ferrand et al. 2013).
#pragma once

#include "core/Vector.hpp"

namespace sph {

struct DeficiencyWeightingBoundaryIntegral {
    static constexpr bool normalised = false;

    template <int D>
    static double weight(double /*distance*/, const Vec<D>& /*direction*/, const Vec<D>& /*normal*/, double /*spacing*/, double area,
                         double /*influenceRadius*/) {
        return area;
    }
};

}  // namespace sph
