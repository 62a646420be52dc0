// What a time integrator sees of the system it advances: the particle sets whose fields it
// steps in place, the right-hand side, the free bodies, and the few model figures its checks
// and tolerances read. physics/FluidSystem implements it; an integrator includes nothing of
// the physics, so another right-hand side (one that exchanges halos, a test's ODE) takes every
// integrator unchanged.
#pragma once

#include "core/ParticleSet.hpp"
#include "core/StageTimers.hpp"
#include "viscosity/Viscosity.hpp"

#include <string>
#include <utility>
#include <vector>

namespace sph {

struct StateOverRanks;

// Which terms an evaluation computes. An implicit-explicit integrator splits the right-hand
// side: the viscous acceleration (implicit) apart from everything else (explicit).
enum class RateTerms { All, AllButViscous, ViscousOnly };

// The scales an adaptive integrator's absolute tolerances are relative to: positions to the
// smoothing length, velocities to the speed of sound, densities to the reference density.
struct StateScales {
    double smoothingLength, speedOfSound, referenceDensity;
};

template <int D>
class IntegrableSystem {
public:
    IntegrableSystem(ParticleSet<D> fluidSet, ParticleSet<D> wallSet) : fluid(std::move(fluidSet)), walls(std::move(wallSet)) {}
    virtual ~IntegrableSystem() = default;
    IntegrableSystem(const IntegrableSystem&) = delete;
    IntegrableSystem& operator=(const IntegrableSystem&) = delete;

    // Fills the fluid's acceleration (and density rate where continuity() holds) and the walls'
    // density rate where wallDensityEvolves(). With ViscousOnly, the acceleration is the
    // viscous term alone and the density rates are zero.
    virtual void evaluateRates(double t, RateTerms terms) = 0;

    // Free bodies, advanced with the fluid by an integrator that can (advancesFreeBodies()).
    virtual void predictBodies(double halfDt) = 0;
    virtual void correctBodies(double dt) = 0;
    virtual std::vector<std::string> freeBodyPatches() const = 0;
    // The wall patches whose model adds a viscous stress among its wall forces, which an
    // evaluation of the viscous terms alone leaves out.
    virtual std::vector<std::string> patchesWithWallViscousStress() const = 0;

    virtual bool continuity() const = 0;          // the fluid's density follows densityRate
    virtual bool wallDensityEvolves() const = 0;  // so does the walls' (dynamic boundary)
    virtual StateScales scales() const = 0;
    virtual const Viscosity& viscosity() const = 0;  // for an implicit viscous solve's Jacobian

    // Fluid position, velocity and density, and wall density: advanced in place.
    ParticleSet<D> fluid;
    ParticleSet<D> walls;
    StageTimers timers;  // an integrator times its own updates as Stage::Integrator
    // True during the step's last evaluation when it is at the state the step ends with
    // (TimeIntegrator::evaluateAtStepEnd): what the system computes from that state after the
    // step may be taken in it (the shifting pass's pair sums, in the force loop).
    bool evaluatingStepEnd = false;
    // Set where the state is shared over ranks (parallel/DistributedSystem), for the SUNDIALS
    // integrators; null in a serial run.
    const StateOverRanks* stateOverRanks = nullptr;
};

}  // namespace sph
