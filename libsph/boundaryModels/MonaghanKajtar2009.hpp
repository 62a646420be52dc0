// Repulsive boundary force of Monaghan & Kajtar (2009), acceleration of fluid particle a by
// wall particle k:
//   f_ak = (K / beta) r_ak / |r_ak|^2 * W^(|r_ak|) * 2 m_k / (m_a + m_k),   beta = dx / s_k
// with W^ = W(r)/W(0) the case's kernel normalised to 1 at contact, so that K is a squared
// velocity independent of h and dx: the force on a particle at the initial gap dx is of order
// K/dx, which balances a wall pressure rho g H when K ~ g H (Monaghan & Kajtar suggest K of
// order g H or c0^2/10). The `shifted` form moves the singularity to |r| = shift (default
// dx/2) and clips the distance at 0.1 dx:  r_ak/|r_ak| / max(|r_ak| - shift, 0.1 dx).
// Reference: J.J. Monaghan, J.B. Kajtar, Comput. Phys. Commun. 180 (2009) 1811-1820, Eq. (3.4).
// Example (constant/boundaryProperties):
//   tank { type monaghanKajtar; K 10; form square; }        // or: form shifted; shift 0.005;
#pragma once

#include "core/Vector.hpp"

#include <algorithm>

namespace sph {

struct MonaghanKajtar2009 {
    double K;
    double dx;           // fluid particle spacing
    double shift;        // 0 for the |r|^2 form
    double minDistance;  // clip of |r| - shift

    // kernelShape = W(r)/W(0); wallSpacing = s_k, so beta = dx/s_k.
    template <int D>
    Vec<D> acceleration(const Vec<D>& r, double distance, double kernelShape, double wallSpacing, double massFluid, double massWall) const {
        const double denominator = distance * std::max(distance - shift, minDistance);
        return (K * wallSpacing / dx * kernelShape * 2.0 * massWall / (massFluid + massWall) / denominator) * r;
    }
};

}  // namespace sph
