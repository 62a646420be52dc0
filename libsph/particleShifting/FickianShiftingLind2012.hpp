// Fickian particle shifting of Lind, Xu, Stansby & Rogers (2012), with the diffusion
// coefficient proportional to the particle's speed (Skillen et al. 2013, as DualSPHysics does):
//   delta r_i = -A h |v_i| dt grad C_i,   grad C_i = sum_j V_j grad_i W_ij,   V_j = m_j / rho_j
// Particles move down the gradient of their concentration, towards where they are sparse. As a
// shifting velocity (delta r_i / dt) it reads
//   delta u_i = -A h |v_i| sum_j V_j grad_i W_ij,   |delta u_i| <= |v_i| / 2,
// the bound as in Sun et al. (2019): a shift never outruns the particle's own motion.
// The free-surface treatment (FreeSurfaceMarrone2010.hpp) and the walls are the pass's
// (physics/ParticleShiftingPass.tpp), the same for every shifting law.
// References: S.J. Lind, R. Xu, P.K. Stansby, B.D. Rogers, J. Comput. Phys. 231 (2012) 1499-1523;
// A. Skillen, S. Lind, P.K. Stansby, B.D. Rogers, CMAME 265 (2013) 163-173.
// Example (system/sphSchemes):   particleShifting { type lind; coefficient 2; }
#pragma once

#include "particleShifting/TensileShiftingWeight.hpp"

namespace sph {

struct FickianShiftingLind2012 {
    static constexpr bool enabled = true;

    FickianShiftingLind2012(double coefficient, double h) : coefficient(coefficient), h(h) {}

    // Each pair's grad W counts once: the plain concentration gradient.
    TensileShiftingWeight pairWeight() const { return {}; }
    // delta u_i = -scale sum_j V_j pairWeight grad_i W_ij, bounded by speedBound.
    double scale(double speed, double /*maxSpeed*/) const { return coefficient * h * speed; }
    double speedBound(double speed, double /*maxSpeed*/) const { return 0.5 * speed; }

    double coefficient, h;
};

}  // namespace sph
