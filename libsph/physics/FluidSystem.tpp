// Implementation of FluidSystem<D>, included once per dimension by FluidSystem<D>.cpp so the
// hot loops of each dimension compile in parallel.
#include "motion/MovingWallPatch.hpp"
#include "physics/FluidSystem.hpp"
#include "physics/FluidRates.tpp"
#include "physics/FluidWallPair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>
#include <stdexcept>

static_assert(sizeof(sph::Vec<3>) == 3 * sizeof(double) && sizeof(sph::Vec<2>) == 2 * sizeof(double), "the pair loop reads Vec<D> arrays as doubles");

namespace sph {

// Whether this build compiles the pair loops of dimension D (CMake option SPHKIT_DIMENSIONS;
// the case reader rejects the others). The rest of the system exists in every dimension.
template <int D>
inline constexpr bool dimensionCompiled = false;
#ifdef SPHKIT_HAS_1D
template <>
inline constexpr bool dimensionCompiled<1> = true;
#endif
#ifdef SPHKIT_HAS_2D
template <>
inline constexpr bool dimensionCompiled<2> = true;
#endif
#ifdef SPHKIT_HAS_3D
template <>
inline constexpr bool dimensionCompiled<3> = true;
#endif
template <int D, class Kernel>
inline constexpr bool pairLoopsCompiled = dimensionCompiled<D>&& compiledKernel<Kernel>;
constexpr const char* pairLoopsNotCompiled = "this pair loop is not compiled (SPHKIT_KERNELS, SPHKIT_DIMENSIONS); the case reader rejects it";

template <int D>
FluidSystem<D>::FluidSystem(FluidModels<D> models, ParticleSet<D> fluidSet, ParticleSet<D> wallSet, std::vector<Patch<D>> patchList,
                            const Vec<D>& domainMin, const Vec<D>& domainMax, const Vec<D>& gravity, double gravityRampTime,
                            const std::array<bool, D>& periodic)
    : IntegrableSystem<D>(std::move(fluidSet), std::move(wallSet)),
      patches(std::move(patchList)),
      models_(std::move(models)),
      domainMin_(domainMin),
      domainMax_(domainMax),
      periodic_(periodic),
      gravity_{gravity, gravityRampTime},
      supportRadius_(std::visit([](const auto& k) { return k.supportRadius(); }, models_.kernel)),
      fluidCells_(domainMin, domainMax, supportRadius_, periodic),
      wallCells_(domainMin, domainMax, supportRadius_, periodic) {
    fluid.add(fields::pressure, 0.0);
    fluid.add(fields::acceleration, Vec<D>::Zero());
    if (continuity()) fluid.add(fields::densityRate, 0.0);
    if (shiftsParticles()) {
        fluid.add(fields::shiftingVelocity, Vec<D>::Zero());
        fluid.add(fields::freeSurfaceLambda, 1.0, false);  // not written: recomputed every step
        shiftingScratch_.weight = models_.shifting.pairWeight();
        shiftingScratch_.inverseWdx = 1.0 / std::visit([&](const auto& k) { return k.value(models_.shifting.dx); }, models_.kernel);
    }
    walls.add(fields::pressure, 0.0);
    walls.add(fields::density, std::visit([](const auto& e) { return e.rho0; }, models_.eos));
    // Written where a patch moves: its velocity is then worth colouring by (and zero elsewhere).
    wallsMove_ = std::any_of(patches.begin(), patches.end(), [](const Patch<D>& p) { return p.motion != nullptr; });
    walls.add(fields::velocity, Vec<D>::Zero(), wallsMove_);
    if (!walls.has(fields::area) && walls.has(fields::spacing)) {
        // A state written before walls had areas: each particle stands for spacing^(D-1).
        auto& area = walls.add(fields::area, 0.0);
        const auto& spacing = walls[fields::spacing];
        for (std::size_t w = 0; w < walls.size(); ++w) area[w] = std::pow(spacing[w], D - 1);
    }
    if (viscous()) walls.add(fields::viscousVelocity, Vec<D>::Zero(), false);
    indexWalls();
    for (Patch<D>& patch : patches) {
        wallDensityEvolves_ = wallDensityEvolves_ || patch.model->evolvesWallDensity();
        keepsUncorrectedAcceleration_ = keepsUncorrectedAcceleration_ || patch.model->needsUncorrectedAcceleration();
        patch.model->addFields(boundaryView(0.0));
    }
    if (wallDensityEvolves_) walls.add(fields::densityRate, 0.0);
    if (keepsUncorrectedAcceleration_) fluid.add(fields::uncorrectedAcceleration, Vec<D>::Zero());
    if (wallsMove_) {
        // Motions are given from the initial configuration: written with the state, so a restart keeps it.
        if (!walls.has(fields::initialPosition)) walls.add(fields::initialPosition, Vec<D>::Zero()) = walls.position;
        if (!walls.has(fields::initialNormal)) walls.add(fields::initialNormal, Vec<D>::Zero()) = walls[fields::normal];
        const bool deforms = std::any_of(patches.begin(), patches.end(), [](const Patch<D>& p) { return p.motion && p.motion->deforms(); });
        if (D >= 2 && deforms && walls.has(fields::area)) {  // areaStretch scales the generated areas and spacings
            if (!walls.has(fields::initialArea)) walls.add(fields::initialArea, 0.0) = walls[fields::area];
            if (!walls.has(fields::initialSpacing)) walls.add(fields::initialSpacing, 0.0) = walls[fields::spacing];
        }
        walls.add(fields::acceleration, Vec<D>::Zero(), false);
        for (Patch<D>& patch : patches)
            patch.surfaceAlongCurve = patch.motion && patch.motion->deforms() && surfaceAlongCurve(walls, patch.begin, patch.end);
    }
    wallCells_.markCellsNearPoints();  // the fluid-wall pass skips the fluid cells with no wall particle near
    wallCells_.build(walls.position, 0, wallParticleEnd_);
}

// Where the wall-particle patches end, and the wall-force patches' own lists.
template <int D>
void FluidSystem<D>::indexWalls() {
    wallParticleEnd_ = patches.empty() ? walls.size() : 0;
    for (Patch<D>& patch : patches) {
        if (patch.model->actsThroughWallParticles()) {
            if (wallParticleEnd_ != patch.begin) throw std::logic_error("wall-particle patches must precede wall-force patches");
            wallParticleEnd_ = patch.end;
        } else {
            if (!patch.cells) {
                patch.cells.emplace(domainMin_, domainMax_, supportRadius_, periodic_);
                patch.cells->markCellsNearPoints();  // the patch's passes over the fluid skip the cells far from it
            }
            patch.cells->build(walls.position, patch.begin, patch.end);
        }
    }
}

template <int D>
void FluidSystem<D>::adoptParticles(ParticleSet<D> fluidSet, ParticleSet<D> wallSet) {
    fluid = std::move(fluidSet);
    walls = std::move(wallSet);
    const auto& patchOfWall = walls[fields::patch];
    std::size_t begin = 0;
    for (std::size_t p = 0; p < patches.size(); ++p) {
        patches[p].begin = begin;
        patches[p].end = begin + static_cast<std::size_t>(std::count(patchOfWall.begin(), patchOfWall.end(), patches[p].wallField));
        begin = patches[p].end;
    }
    if (!patches.empty() && begin != walls.size()) throw std::logic_error("adoptParticles: walls of no patch, or of a patch that had none");
    indexWalls();
    wallCells_.build(walls.position, 0, wallParticleEnd_);
}

template <int D>
bool FluidSystem<D>::wrapPeriodic() {
    bool moved = false;
    for (int d = 0; d < D; ++d) {
        if (!periodic_[static_cast<std::size_t>(d)]) continue;
        const double lower = domainMin_[d], extent = domainMax_[d] - domainMin_[d];
        for (Vec<D>& x : fluid.position) {
            const double periods = std::floor((x[d] - lower) / extent);
            if (periods == 0.0) continue;
            x[d] -= extent * periods;
            moved = true;
        }
    }
    return moved;
}

template <int D>
void FluidSystem<D>::moveWalls(double t) {
    auto timer = timers.time(Stage::Boundary);
    for (Patch<D>& patch : patches) {
        if (!patch.motion) continue;
        moveWallPatch(walls, *patch.motion, patch.begin, patch.end, t, patch.surfaceAlongCurve);
        if (patch.cells) patch.cells->build(walls.position, patch.begin, patch.end);
    }
    wallCells_.build(walls.position, 0, wallParticleEnd_);
}

template <int D>
double FluidSystem<D>::smoothingLength() const {
    return std::visit([](const auto& k) { return k.h; }, models_.kernel);
}

template <int D>
StateScales FluidSystem<D>::scales() const {
    const auto [speedOfSound, referenceDensity] = std::visit([](const auto& e) { return std::pair(e.c0, e.rho0); }, models_.eos);
    return {smoothingLength(), speedOfSound, referenceDensity};
}

template <int D>
Vec<D> FluidSystem<D>::gravityAt(double t) const {
    return gravity_.at(t);
}

template <int D>
BoundaryView<D> FluidSystem<D>::boundaryView(double t) {
    return {fluid, walls, fluidCells_, wallCells_, models_.kernel, models_.eos, supportRadius_, continuity(), gravityAt(t)};
}

template <int D>
FluidSystemView<D> FluidSystem<D>::view() const {
    return {fluid,     walls,      patches,    fluidCells_, wallCells_, models_.kernel, models_.viscosity, supportRadius_, smoothingLength(),
            viscous(), domainMin_, domainMax_, gravity_};
}

template <int D>
void FluidSystem<D>::sortFluidByCell() {
    auto timer = timers.time(Stage::Neighbours);
    fluid.permute(fluidCells_.cellOrder(fluid.position));
}

template <int D>
void FluidSystem<D>::evaluateRates(double t, RateTerms terms) {
    if (wallsMove_) moveWalls(t);
    // The hooks of a decomposed run lie outside the stages' timers: it times its exchanges itself.
    if (afterWallMotion) afterWallMotion();
    {
        auto timer = timers.time(Stage::Neighbours);
        fluidCells_.build(fluid.position);
    }
    if (!continuity()) {
        {
            auto timer = timers.time(Stage::Density);
            computeSummationDensity();
        }
        if (afterSummationDensity) afterSummationDensity();
    }
    {
        auto timer = timers.time(Stage::Density);
        computeFluidPressure();
    }
    {
        auto timer = timers.time(Stage::Boundary);
        const BoundaryView<D> view = boundaryView(t);
        for (Patch<D>& patch : patches)
            if (!patch.cells) patch.model->updateWalls(view, patch.begin, patch.end);
    }
    if (afterWallUpdate) afterWallUpdate();
    {
        auto timer = timers.time(Stage::Forces);
        computeForces(gravityAt(t), terms);
    }
    if (terms != RateTerms::ViscousOnly) addWallForces(t);
    if (afterRates) afterRates();
}

template <int D>
void FluidSystem<D>::addWallForces(double t) {
    auto timer = timers.time(Stage::Boundary);
    if (keepsUncorrectedAcceleration_) fluid[fields::uncorrectedAcceleration] = fluid[fields::acceleration];
    if (fluid.has(fields::boundaryCorrection))
        std::fill(fluid[fields::boundaryCorrection].begin(), fluid[fields::boundaryCorrection].end(), Vec<D>::Zero());
    auto& acceleration = fluid[fields::acceleration];
    const BoundaryView<D> view = boundaryView(t);
    for (Patch<D>& patch : patches) {
        if (!patch.cells) continue;
        const bool free = patch.motion && patch.motion->isFree();
        std::vector<Vec<D>> before;
        if (free || patch.recordsLoad) before = acceleration;
        patch.model->addWallForces(view, *patch.cells, patch.begin, patch.end);
        if (patch.recordsLoad) recordLoad(patch, before);
        if (!free) continue;
        std::vector<BodyLoadShare<D>> shares = bodyLoadShares(*patch.motion, fluid, before);
        if (bodyLoadsOverRanks) shares = bodyLoadsOverRanks(shares);
        loadFreeBody(*patch.motion, shares, gravityAt(t), t);
    }
}

template <int D>
void FluidSystem<D>::recordLoad(Patch<D>& patch, const std::vector<Vec<D>>& accelerationBefore) const {
    const auto& acceleration = fluid[fields::acceleration];
    const double* m = fluid[fields::mass].data();
    patch.load = {};
    for (std::size_t i = 0; i < fluid.ownedCount(); ++i) {
        if (ownedFluid && !(*ownedFluid)[i]) continue;  // a copy: its owner adds it
        const Vec<D> force = -m[i] * (acceleration[i] - accelerationBefore[i]);
        if (force == Vec<D>::Zero()) continue;  // beyond the patch's reach
        for (int d = 0; d < D; ++d) patch.load[static_cast<std::size_t>(d)].add(force[d]);
    }
}

template <int D>
void FluidSystem<D>::predictBodies(double halfDt) {
    for (Patch<D>& patch : patches)
        if (patch.motion && patch.motion->isFree()) patch.motion->predict(halfDt);
}

template <int D>
void FluidSystem<D>::correctBodies(double dt) {
    for (Patch<D>& patch : patches)
        if (patch.motion && patch.motion->isFree()) patch.motion->correct(dt);
}

template <int D>
std::vector<std::string> FluidSystem<D>::freeBodyPatches() const {
    std::vector<std::string> names;
    for (const Patch<D>& patch : patches)
        if (patch.motion && patch.motion->isFree()) names.push_back(patch.name);
    return names;
}

template <int D>
std::vector<std::string> FluidSystem<D>::patchesWithWallViscousStress() const {
    std::vector<std::string> names;
    for (const Patch<D>& patch : patches)
        if (patch.model && patch.model->addsViscousStress()) names.push_back(patch.name);
    return names;
}

template <int D>
void FluidSystem<D>::computeSummationDensity() {
    std::visit(
        [this](const auto& kernel) {
            if constexpr (!pairLoopsCompiled<D, std::decay_t<decltype(kernel)>>) {
                throw std::logic_error(pairLoopsNotCompiled);
            } else {
                const std::size_t n = this->fluid.ownedCount();
                const Vec<D>* x = this->fluid.position.data();
                const double* mass = this->fluid[fields::mass].data();
                const double* wallMass = this->walls[fields::mass].data();
                double* rho = this->fluid[fields::density].data();
                const double radius = supportRadius_;
#pragma omp parallel for schedule(static)
                for (std::size_t i = 0; i < n; ++i) {
                    double sum = 0.0;
                    fluidCells_.forEachNeighbour(x[i], radius,
                                                 [&](std::uint32_t j, const Vec<D>&, double r2) { sum += mass[j] * kernel.value(std::sqrt(r2)); });
                    wallCells_.forEachNeighbour(x[i], radius,
                                                [&](std::uint32_t j, const Vec<D>&, double r2) { sum += wallMass[j] * kernel.value(std::sqrt(r2)); });
                    rho[i] = sum;
                }
            }
        },
        models_.kernel);
}

template <int D>
void FluidSystem<D>::computeFluidPressure() {
    std::visit(
        [this](const auto& eos) {
            const std::size_t n = fluid.ownedCount();
            const double* rho = fluid[fields::density].data();
            double* p = fluid[fields::pressure].data();
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i) p[i] = eos.pressure(rho[i]);
        },
        models_.eos);
}

// A variant family with one more alternative.
template <class Family, class Extra>
struct AppendAlternative;
template <class... Models, class Extra>
struct AppendAlternative<std::variant<Models...>, Extra> {
    using type = std::variant<Models..., Extra>;
};

template <int D>
void FluidSystem<D>::computeForces(const Vec<D>& gravity, RateTerms terms) {
    if (auto* fourtakas = std::get_if<Fourtakas2019<D>>(&models_.diffusion)) fourtakas->setGravity(gravity, supportRadius_);
    // The diffusion as the pair loop evaluates it: Fourtakas' term beyond its series' reach is a
    // type of its own, so that the loop over pairs never branches to std::pow.
    using PairDiffusion = AppendAlternative<DensityDiffusion<D>, Fourtakas2019<D, false>>::type;
    const PairDiffusion pairDiffusion = std::visit(
        [](const auto& diffusion) -> PairDiffusion {
            if constexpr (std::is_same_v<std::decay_t<decltype(diffusion)>, Fourtakas2019<D>>)
                if (!diffusion.seriesHolds) return diffusion.beyondSeries();
            return diffusion;
        },
        models_.diffusion);
    // With shifting, the step's last evaluation of every term takes the shifting pass's pair sums
    // on the pairs it lists: the pass reuses them if the state is still this one when it runs.
    ParticleShiftingScratch<D>* const shiftingSums =
        shiftsParticles() && terms == RateTerms::All && this->evaluatingStepEnd ? &shiftingScratch_ : nullptr;
    shiftingScratch_.summedByRates = shiftingSums != nullptr;
    const auto dispatch = [&]<bool ViscousOnly>(const auto& kernel, const auto& viscosity, const auto& diffusion) {
        using Diffusion = std::decay_t<decltype(diffusion)>;
        if constexpr (!pairLoopsCompiled<D, std::decay_t<decltype(kernel)>>) {
            throw std::logic_error(pairLoopsNotCompiled);
        } else if (continuity()) {
            fluidRates<D, true, ViscousOnly>(*this, cellOrdered_, shiftingSums, kernel, viscosity, diffusion, gravity);
        } else if constexpr (!Diffusion::enabled) {  // the case reader rejects diffusion with summation density
            fluidRates<D, false, ViscousOnly>(*this, cellOrdered_, shiftingSums, kernel, viscosity, diffusion, gravity);
        }
    };
    std::visit(
        [&](const auto& kernel, const auto& viscosity, const auto& diffusion) {
            using Viscosity = std::decay_t<decltype(viscosity)>;
            if (terms == RateTerms::All) {
                dispatch.template operator()<false>(kernel, viscosity, diffusion);
            } else if constexpr (Viscosity::enabled) {  // without viscosity the split is trivial
                if (terms == RateTerms::AllButViscous)
                    dispatch.template operator()<false>(kernel, NoViscosity{}, diffusion);
                else
                    dispatch.template operator()<true>(kernel, viscosity, NoDensityDiffusion{});
            } else if (terms == RateTerms::AllButViscous) {
                dispatch.template operator()<false>(kernel, viscosity, diffusion);
            } else {
                std::fill(this->fluid[fields::acceleration].begin(), this->fluid[fields::acceleration].end(), Vec<D>::Zero());
                if (continuity()) std::fill(this->fluid[fields::densityRate].begin(), this->fluid[fields::densityRate].end(), 0.0);
            }
        },
        models_.kernel, models_.viscosity, pairDiffusion);
}

template <int D>
bool FluidSystem<D>::viscous() const {
    return std::visit([](const auto& v) { return v.enabled; }, models_.viscosity);
}

template <int D>
double FluidSystem<D>::stableTimeStep(double courant, bool viscousLimit) const {
    const std::size_t n = fluid.ownedCount();
    const Vec<D>* v = fluid[fields::velocity].data();
    const Vec<D>* a = fluid[fields::acceleration].data();
    double maxSpeed2 = 0.0, maxAcceleration2 = 0.0;
#pragma omp parallel for reduction(max : maxSpeed2, maxAcceleration2) schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        maxSpeed2 = std::max(maxSpeed2, v[i].squaredNorm());
        maxAcceleration2 = std::max(maxAcceleration2, a[i].squaredNorm());
    }
    const double h = smoothingLength();
    const double c0 = std::visit([](const auto& e) { return e.c0; }, models_.eos);
    double dt = courant * h / (c0 + std::sqrt(maxSpeed2));
    if (maxAcceleration2 > 0.0) dt = std::min(dt, courant * std::sqrt(h / std::sqrt(maxAcceleration2)));
    const double nu = viscousTimeStepNu(models_.viscosity);
    if (nu > 0.0 && viscousLimit) dt = std::min(dt, 0.125 * h * h / nu);
    return dt;
}

}  // namespace sph

#include "physics/ParticleShiftingPass.tpp"
