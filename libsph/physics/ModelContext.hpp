// What a per-pair model needs to know of the case when it is built.
#pragma once

namespace sph {

struct ModelContext {
    double dx;         // particle spacing
    double h;          // smoothing length
    double c0;         // reference speed of sound
    double rho0;       // reference density
    double nu;         // kinematic viscosity (0 when the fluid properties give none)
    double stiffness;  // K of the equation of state p - p0 = K ((rho/rho0)^n - 1)
    double exponent;   // n of the same
    // The fluid's viscosity is artificial (Monaghan's): a wall's viscous velocity then only
    // damps, and a no-slip wall acts as friction (DummyParticlesAdami2012.hpp).
    bool artificialViscosity = false;
    // The fluid's viscosity is laminar (Morris'): the deficiency correction's virtual particles
    // then carry its stress at a no-slip wall (DeficiencyCorrection.hpp).
    bool laminarViscosity = false;
};

}  // namespace sph
