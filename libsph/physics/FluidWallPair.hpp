// The momentum terms a wall particle w adds to the acceleration of fluid particle i, with
// r = x_i - x_w and F = W'(|r|)/|r|:
//   -m_w (p_i/rho_i^2 + p_w/rho_w^2) F r                                  (pressure)
//   + m_w Pi(v_i - v~_w, r) (r, or v_i - v~_w, as the viscosity model says) (viscosity)
// with v~_w the wall's viscous velocity (no-slip or free-slip, set by its boundary model).
// The fluid's pair loop adds them; the forces function object reports their reaction, so the
// two cannot disagree.
#pragma once

#include "core/Vector.hpp"

#include <cstddef>

namespace sph {

// eta^2 = 0.01 h^2 keeps the viscous 1/r^2 finite (Monaghan 1992).
inline double viscousRegularisation(double smoothingLength) { return 0.01 * smoothingLength * smoothingLength; }

template <int D>
struct WallPairFields {
    const double* mass;
    const double* pressure;
    const double* density;
    const Vec<D>* viscousVelocity;  // read only by a viscous case
};

template <bool Pressure, class Viscosity, int D>
inline Vec<D> fluidWallAcceleration(const Viscosity& viscosity, const Vec<D>& r, double r2, double F, double eta2, double pOverRho2, double rhoFluid,
                                    const Vec<D>& vFluid, const WallPairFields<D>& wall, std::size_t w) {
    Vec<D> acceleration = Vec<D>::Zero();
    if constexpr (Pressure) acceleration -= (wall.mass[w] * (pOverRho2 + wall.pressure[w] / (wall.density[w] * wall.density[w])) * F) * r;
    if constexpr (Viscosity::enabled) {
        const Vec<D> viw = vFluid - wall.viscousVelocity[w];
        const double factor = viscosity.pairFactor(viw.dot(r), r2, 1.0 / (r2 + eta2), rhoFluid, wall.density[w], F);
        acceleration += (wall.mass[w] * factor) * (Viscosity::alongSeparation ? r : viw);
    }
    return acceleration;
}

}  // namespace sph
