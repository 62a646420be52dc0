// Free-surface detection of Marrone, Colagrossi, Le Touze & Graziani (2010), as particle
// shifting uses it. The smallest eigenvalue lambda_i of the moment matrix
//   M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij
// is 1 in a full support and about 1/2 on a flat free surface (Wendland C2 on a square lattice,
// h = 1.3 dx: 0.487 on the top row, 0.905 one row down, 0.974 below, the lattice's sum short of
// the integral; h = 2 dx: 0.500, 0.700, 0.943, then 0.999). Its
// outward normal is n_i = -M_i^-1 grad C_i / |M_i^-1 grad C_i|, grad C_i = sum_j V_j grad_i W_ij.
// Walls complete both sums, so that a wall does not look like a free surface: wall particles
// with a volume as fluid particles; a one-layer wall (wall-force patches) by its surface
// elements a (area A_a, normal n_a into the fluid, r_ia = x_i - x_a):
//   M_i += phi_i I + sum_a A_a W_ia r_ia (x) n_a,   grad C_i -= sum_a A_a W_ia n_a,
// phi_i the kernel's volume behind the wall (KernelOutsideFraction.hpp), from the divergence
// theorem applied to the kernel over the space behind the wall.
// Shifting then treats three kinds of particle:
//   lambda_i < splash (0.4)                 none: too few neighbours to say where the surface is
//   lambda_i < surface (0.55), or a neighbour within the support is:
//                                           the shift's component along the surface's normal is
//                                           removed, the normal being the kernel-weighted mean
//                                           of the free-surface particles' n_j within the support
//                                           (a particle below the surface has nearly complete
//                                           sums: its own n_i is noise)
//   otherwise                               the whole shift
// Reference: S. Marrone, A. Colagrossi, D. Le Touze, G. Graziani, J. Comput. Phys. 229 (2010)
// 3652-3663; the thresholds as P.N. Sun et al. (2017) use them.
// Example (system/sphSchemes):   particleShifting { type sun; surfaceLambda 0.55; splashLambda 0.4; }
#pragma once

namespace sph {

struct FreeSurfaceMarrone2010 {
    double surfaceLambda = 0.55;
    double splashLambda = 0.4;
};

}  // namespace sph
