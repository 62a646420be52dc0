// The particles of a case and the models selected for them, and the right-hand side every
// integrator calls: from positions, velocities and densities to accelerations and density rates.
//
// One evaluation runs these stages; a stage with nothing selected costs nothing:
//   0. wall motion  moving patches take their prescribed position, velocity, acceleration and
//                   normal at t (normals and spacings recomputed on a deforming patch)
//   1. neighbours   cell-linked list of the fluid (walls re-indexed only when they move)
//   2. density      summation density (if selected), then pressure from the equation of state
//   3. boundary     each wall-particle patch's model sets its particles' pressure, density,
//                   velocity
//   4. forces       pressure gradient, viscosity, gravity, continuity rate and density diffusion
//                   over fluid-fluid and fluid-wall pairs: a loop driver (FluidRates.tpp) templated
//                   on the kernel, viscosity, density diffusion and density formulation (one
//                   std::visit), calling the pair physics (FluidPairTerms.hpp, FluidWallPair.hpp)
//   5. wall forces  repulsion and deficiency-correction patches add their accelerations; the
//                   acceleration of stage 4 is kept as uncorrectedAcceleration when one of them
//                   reads it
// Particle shifting, where selected, is no part of the right-hand side: the driver calls
// shiftParticles after every step.
// The wall set holds the wall-particle patches first, then the wall-force patches; only the
// first enter the kernel sums.
#pragma once

#include "boundaryModels/BoundaryModel.hpp"
#include "core/ParticleSet.hpp"
#include "densityDiffusion/DensityDiffusion.hpp"
#include "equationsOfState/EquationOfState.hpp"
#include "kernels/Kernel.hpp"
#include "motion/MovingWallPatch.hpp"
#include "physics/CellOrderedFluid.hpp"
#include "physics/FluidSystemView.hpp"
#include "physics/Gravity.hpp"
#include "physics/Patch.hpp"
#include "physics/ParticleShiftingScratch.hpp"
#include "particleShifting/ParticleShifting.hpp"
#include "neighbourSearch/CellLinkedList.hpp"
#include "timeIntegrators/IntegrableSystem.hpp"
#include "viscosity/Viscosity.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sph {

enum class DensityFormulation { Summation, Continuity };

template <int D>
struct FluidModels {
    Kernel<D> kernel;
    EquationOfState eos;
    Viscosity viscosity;
    DensityDiffusion<D> diffusion;
    DensityFormulation density = DensityFormulation::Continuity;
    ParticleShifting shifting{};  // none unless the case selects one
};

// What an integrator sees of it, the particle sets and the right-hand side, is its base
// IntegrableSystem (timeIntegrators/IntegrableSystem.hpp).
template <int D>
class FluidSystem final : public IntegrableSystem<D> {
public:
    // Inside a generic lambda GCC 12 still needs this->fluid, this->walls.
    using IntegrableSystem<D>::fluid;
    using IntegrableSystem<D>::walls;
    using IntegrableSystem<D>::timers;

    // Takes the particle sets as read from the state files: the fluid set must hold velocity,
    // density and mass; the wall set position, normal, area, mass and patch, sorted by patch.
    FluidSystem(FluidModels<D> models, ParticleSet<D> fluid, ParticleSet<D> walls, std::vector<Patch<D>> patches, const Vec<D>& domainMin,
                const Vec<D>& domainMax, const Vec<D>& gravity, double gravityRampTime, const std::array<bool, D>& periodic = {});

    // Free bodies: the integrator advances them with the fluid (see FreeBody2D).
    void predictBodies(double halfDt) override;
    void correctBodies(double dt) override;
    std::vector<std::string> freeBodyPatches() const override;
    std::vector<std::string> patchesWithWallViscousStress() const override;

    // Takes other particles with the fields of these (a rank's share of a decomposed case, owned
    // particles and halo copies together, walls in the order of the set they replace): each
    // patch's range follows the walls' patch field, and the wall lists are rebuilt.
    void adoptParticles(ParticleSet<D> fluidSet, ParticleSet<D> wallSet);

    // Brings fluid particles that crossed a periodic side back into the domain; call between
    // steps. Returns whether any particle moved.
    bool wrapPeriodic();
    const std::array<bool, D>& periodic() const { return periodic_; }

    // Fills acceleration (and density rate with continuity) of the fluid, and the wall state.
    // With ViscousOnly, the acceleration is the viscous term alone and the density rates are zero.
    // The cell lists refer to the particle arrays of this object, which never moves (its base
    // is neither copied nor moved).
    void evaluateRates(double t, RateTerms terms = RateTerms::All) override;

    // Moves every fluid particle by dt times its shifting velocity (written as the field
    // shiftingVelocity), from the state at the end of a step; call between steps only. Leaves
    // each particle's free-surface indicator in the unwritten field freeSurfaceLambda.
    void shiftParticles(double dt);
    bool shiftsParticles() const { return models_.shifting.enabled(); }

    // Reorders the fluid by cell for memory locality; call between steps only.
    void sortFluidByCell();

    // Largest stable step: CFL on h/(c0 + max|v|) and sqrt(h/max|a|), and 0.125 h^2/nu unless
    // the integrator treats viscosity implicitly.
    double stableTimeStep(double courant, bool viscousLimit = true) const;
    bool viscous() const;

    Vec<D> gravityAt(double t) const;
    double smoothingLength() const;
    double supportRadius() const { return supportRadius_; }
    bool continuity() const override { return models_.density == DensityFormulation::Continuity; }
    bool wallDensityEvolves() const override { return wallDensityEvolves_; }
    StateScales scales() const override;
    const Viscosity& viscosity() const override { return models_.viscosity; }
    const FluidModels<D>& models() const { return models_; }
    const Vec<D>& domainMin() const { return domainMin_; }
    const Vec<D>& domainMax() const { return domainMax_; }
    // What a boundary model sees of the system at time t, and what post-processing reads.
    BoundaryView<D> boundaryView(double t);
    FluidSystemView<D> view() const;

    std::vector<Patch<D>> patches;

    // Where a decomposed run's halo copies take their owners' values within an evaluation: after
    // the walls moved (a curve's normals, spacings and areas, which its pieces' ends cannot
    // compute), after summation density (the fluid's density), after the wall-particle models'
    // update (the walls' state) and at the end (the rates the integrator advances). Empty in a
    // serial run.
    std::function<void()> afterWallMotion, afterSummationDensity, afterWallUpdate, afterRates;
    // The largest of every rank's values, where a pass needs a maximum over all particles (the
    // shifting's bound by the fastest particle). Empty in a serial run.
    std::function<double(double)> largestOverRanks;
    // Every rank's shares of a free body's loads, in the order the serial run sums them. Empty in
    // a serial run.
    std::function<std::vector<BodyLoadShare<D>>(const std::vector<BodyLoadShare<D>>&)> bodyLoadsOverRanks;
    // Per fluid particle, whether this rank uses the rates it computes: its owned particles, where
    // the copies take their owners' rates and no model reads a copy's within the evaluation. The
    // pair loop then skips the pairs of two particles in cells where none is wanted. Null in a
    // serial run: every particle's.
    const std::vector<char>* ratesWanted = nullptr;
    // Per fluid particle, whether this rank owns it (a patch's recorded load sums the owned
    // ones'). Null in a serial run: every particle.
    const std::vector<char>* ownedFluid = nullptr;

    const CellLinkedList<D>& fluidCells() const { return fluidCells_; }
    const CellLinkedList<D>& wallCells() const { return wallCells_; }
    // What the pair loop copied and allocated in the last evaluation (for memory accounting).
    const CellOrderedFluid<D>& cellOrderedFluid() const { return cellOrdered_; }

private:
    void computeSummationDensity();
    void computeFluidPressure();
    void computeForces(const Vec<D>& gravity, RateTerms terms);
    // Whether the last evaluation's force loop took the shifting pairs' sums at the present state.
    bool stateAsShiftingSummed() const;
    void addWallForces(double t);
    // Patch::load from the fluid's acceleration before and after the patch's wall forces.
    void recordLoad(Patch<D>& patch, const std::vector<Vec<D>>& accelerationBefore) const;
    void moveWalls(double t);
    void indexWalls();

    FluidModels<D> models_;
    Vec<D> domainMin_, domainMax_;
    std::array<bool, D> periodic_;
    Gravity<D> gravity_;
    double supportRadius_;
    bool wallDensityEvolves_ = false;
    bool keepsUncorrectedAcceleration_ = false;
    bool wallsMove_ = false;
    std::size_t wallParticleEnd_ = 0;  // walls [0, wallParticleEnd_) enter the kernel sums
    CellLinkedList<D> fluidCells_;
    CellLinkedList<D> wallCells_;
    CellOrderedFluid<D> cellOrdered_;
    ParticleShiftingScratch<D> shiftingScratch_;
};

}  // namespace sph
