// Lennard-Jones-like repulsion of Monaghan (1994), acceleration of fluid particle a by wall
// particle k, acting only closer than r0:
//   f_ak = Dc [ (r0/|r_ak|)^p1 - (r0/|r_ak|)^p2 ] r_ak / |r_ak|^2     for |r_ak| < r0
// Dc is a squared velocity of the order of the largest g H; r0 the initial spacing;
// p1 = 12, p2 = 4 as in the paper.
// Reference: J.J. Monaghan, J. Comput. Phys. 110 (1994) 399-406, Eq. (4.1).
// Example (constant/boundaryProperties):
//   tank { type lennardJones; Dc 10; r0 0.01; p1 12; p2 4; }
#pragma once

#include "core/Vector.hpp"

#include <cmath>

namespace sph {

struct LennardJonesMonaghan1994 {
    double Dc, r0;
    int p1, p2;

    double range() const { return r0; }

    template <int D>
    Vec<D> acceleration(const Vec<D>& r, double distance) const {
        if (distance >= r0) return Vec<D>::Zero();
        const double ratio = r0 / distance;
        return (Dc * (std::pow(ratio, p1) - std::pow(ratio, p2)) / (distance * distance)) * r;
    }
};

}  // namespace sph
