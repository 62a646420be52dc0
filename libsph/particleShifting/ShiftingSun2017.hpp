// The particle shifting technique of the delta+-SPH model of Sun, Colagrossi, Marrone & Zhang
// (2017), with the anti-clumping term of Monaghan's tensile correction inside the sum:
//   delta r_i = -CFL Ma (2h)^2 sum_j [1 + R (W_ij / W(dx))^n] V_j grad_i W_ij,   Ma = U_max / c0
// With the step of its CFL condition, dt = CFL h / c0, CFL Ma (2h)^2 = 4 h U_max dt, so as a
// shifting velocity
//   delta u_i = -4 h U_max sum_j [1 + R (W_ij / W(dx))^n] V_j grad_i W_ij,   |delta u_i| <= U_max / 2,
// the bound of Sun et al. (2019). U_max is the largest fluid speed at the step. The free-surface
// treatment and the walls are the pass's (physics/ParticleShiftingPass.tpp).
// References: P.N. Sun, A. Colagrossi, S. Marrone, A.M. Zhang, Comput. Phys. Commun. 215 (2017)
// 179-193; P.N. Sun, A. Colagrossi, S. Marrone, M. Antuono, A.M. Zhang, CMAME 348 (2019) 912-934.
// Example (system/sphSchemes):   particleShifting { type sun; R 0.2; n 4; }
#pragma once

#include "particleShifting/TensileShiftingWeight.hpp"

namespace sph {

struct ShiftingSun2017 {
    static constexpr bool enabled = true;

    ShiftingSun2017(double R, int n, double h) : R(R), n(n), h(h) {}

    // 1 + R (W_ij / W(dx))^n: pairs closer than dx push harder (Monaghan's tensile term).
    TensileShiftingWeight pairWeight() const { return {R, n}; }
    double scale(double /*speed*/, double maxSpeed) const { return 4.0 * h * maxSpeed; }
    double speedBound(double /*speed*/, double maxSpeed) const { return 0.5 * maxSpeed; }

    double R;
    int n;
    double h;
};

}  // namespace sph
