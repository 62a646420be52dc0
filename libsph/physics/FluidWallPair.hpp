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

// Whether a viscosity adds a term along the relative velocity (Morris) rather than along r: only
// then does a pair loop evaluate one; with any other it is left out, not multiplied by zero.
template <class Viscosity>
inline constexpr bool actsAlongVelocity = [] {
    if constexpr (Viscosity::enabled)
        return !Viscosity::alongSeparation;
    else
        return false;
}();

template <int D>
struct WallPairFields {
    const double* mass;
    const double* pressure;
    const double* density;
    const Vec<D>* viscousVelocity;  // read only by a viscous case
};

// The same terms as two numbers, alongR r + alongV (v_i - v~_w), from (v_i - v~_w).r and wall
// particle w's mass, pressure and density: plain numbers, so a loop in vector lanes can use it.
template <bool Pressure, class Viscosity>
inline void fluidWallFactors(const Viscosity& viscosity, double viwDotR, double r2, double F, double eta2, double pOverRho2, double rhoFluid,
                             double wallMass, double wallPressure, double wallDensity, double& alongR, double& alongV) {
    alongR = 0.0;
    alongV = 0.0;
    if constexpr (Pressure) alongR -= wallMass * (pOverRho2 + wallPressure / (wallDensity * wallDensity)) * F;
    if constexpr (Viscosity::enabled) {
        const double factor = wallMass * viscosity.pairFactor(viwDotR, r2, 1.0 / (r2 + eta2), rhoFluid, wallDensity, F);
        if constexpr (Viscosity::alongSeparation)
            alongR += factor;
        else
            alongV += factor;
    }
}

template <bool Pressure, class Viscosity, int D>
inline Vec<D> fluidWallAcceleration(const Viscosity& viscosity, const Vec<D>& r, double r2, double F, double eta2, double pOverRho2, double rhoFluid,
                                    const Vec<D>& vFluid, const WallPairFields<D>& wall, std::size_t w) {
    const Vec<D> viw = Viscosity::enabled ? Vec<D>(vFluid - wall.viscousVelocity[w]) : Vec<D>::Zero();
    const double viwDotR = Viscosity::enabled ? viw.dot(r) : 0.0;
    double alongR = 0.0, alongV = 0.0;
    fluidWallFactors<Pressure>(viscosity, viwDotR, r2, F, eta2, pOverRho2, rhoFluid, wall.mass[w], wall.pressure[w], wall.density[w], alongR, alongV);
    if constexpr (actsAlongVelocity<Viscosity>)
        return alongR * r + alongV * viw;
    else
        return alongR * r;
}

}  // namespace sph
