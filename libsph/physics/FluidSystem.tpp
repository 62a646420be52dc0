// Implementation of FluidSystem<D>, included once per dimension by FluidSystem<D>.cpp so the
// hot loops of each dimension compile in parallel.
#include "physics/FluidSystem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace sph {

template <int D>
FluidSystem<D>::FluidSystem(FluidModels<D> models, ParticleSet<D> fluidSet, ParticleSet<D> wallSet, std::vector<Patch<D>> patchList,
                            const Vec<D>& domainMin, const Vec<D>& domainMax, const Vec<D>& gravity, double gravityRampTime,
                            const std::array<bool, D>& periodic)
    : fluid(std::move(fluidSet)), walls(std::move(wallSet)), patches(std::move(patchList)), models_(std::move(models)),
      domainMin_(domainMin), domainMax_(domainMax), periodic_(periodic), gravity_(gravity), gravityRampTime_(gravityRampTime),
      supportRadius_(std::visit([](const auto& k) { return k.supportRadius(); }, models_.kernel)),
      fluidCells_(domainMin, domainMax, supportRadius_, periodic), wallCells_(domainMin, domainMax, supportRadius_, periodic) {
    fluid.addScalar("pressure", 0.0);
    fluid.addVector("acceleration", Vec<D>::Zero());
    if (continuity()) fluid.addScalar("densityRate", 0.0);
    walls.addScalar("pressure", 0.0);
    walls.addScalar("density", std::visit([](const auto& e) { return e.rho0; }, models_.eos));
    walls.addVector("velocity", Vec<D>::Zero(), false);
    if (viscous()) walls.addVector("viscousVelocity", Vec<D>::Zero(), false);
    wallParticleEnd_ = patches.empty() ? walls.size() : 0;
    for (Patch<D>& patch : patches) {
        if (patch.model->actsThroughWallParticles()) {
            if (wallParticleEnd_ != patch.begin) throw std::logic_error("wall-particle patches must precede wall-force patches");
            wallParticleEnd_ = patch.end;
        } else {
            patch.cells.emplace(domainMin, domainMax, supportRadius_, periodic);
            patch.cells->build(walls.position, patch.begin, patch.end);
        }
        wallDensityEvolves_ = wallDensityEvolves_ || patch.model->evolvesWallDensity();
        keepsUncorrectedAcceleration_ = keepsUncorrectedAcceleration_ || patch.model->needsUncorrectedAcceleration();
        patch.model->addFields(*this);
    }
    if (wallDensityEvolves_) walls.addScalar("densityRate", 0.0);
    if (keepsUncorrectedAcceleration_) fluid.addVector("uncorrectedAcceleration", Vec<D>::Zero());
    for (const Patch<D>& patch : patches) wallsMove_ = wallsMove_ || patch.motion != nullptr;
    if (wallsMove_) {
        // Motions are given from the initial configuration: written with the state, so a restart keeps it.
        if (!walls.hasVector("initialPosition")) walls.addVector("initialPosition", Vec<D>::Zero()) = walls.position;
        if (!walls.hasVector("initialNormal")) walls.addVector("initialNormal", Vec<D>::Zero()) = walls.vector("normal");
        walls.addVector("acceleration", Vec<D>::Zero(), false);
    }
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
    const auto& x0 = walls.vector("initialPosition");
    const auto& n0 = walls.vector("initialNormal");
    auto& velocity = walls.vector("velocity");
    auto& acceleration = walls.vector("acceleration");
    auto& normal = walls.vector("normal");
    for (Patch<D>& patch : patches) {
        if (!patch.motion) continue;
        for (std::size_t w = patch.begin; w < patch.end; ++w) {
            const Kinematics<D> k = patch.motion->at(x0[w], n0[w], t);
            walls.position[w] = k.position;
            velocity[w] = k.velocity;
            acceleration[w] = k.acceleration;
            normal[w] = patch.motion->normalAt(n0[w], t);
        }
        if (patch.motion->deforms()) recomputeSurface(patch);
        if (patch.cells) patch.cells->build(walls.position, patch.begin, patch.end);
    }
    wallCells_.build(walls.position, 0, wallParticleEnd_);
}

template <int D>
void FluidSystem<D>::recomputeSurface(const Patch<D>& patch) {
    // 2D: the surface particles (layer 0) lie in order along the patch; the normal is the
    // neighbours' chord turned by 90 degrees to the side of the initial normal, the spacing
    // the mean distance to the neighbours. A closed curve wraps around.
    if constexpr (D == 2) {
        const auto& layer = walls.integer("layer");
        auto& normal = walls.vector("normal");
        auto& spacing = walls.scalar("spacing");
        const auto& n0 = walls.vector("initialNormal");
        std::vector<std::size_t> surface;
        for (std::size_t w = patch.begin; w < patch.end; ++w)
            if (layer[w] == 0) surface.push_back(w);
        const std::size_t m = surface.size();
        if (m < 3) return;
        const auto& x = walls.position;
        const bool closed = (x[surface.front()] - x[surface.back()]).norm() < 1.5 * spacing[surface.front()];
        for (std::size_t k = 0; k < m; ++k) {
            const bool first = k == 0, last = k + 1 == m;
            const std::size_t previous = first ? (closed ? surface[m - 1] : surface[k]) : surface[k - 1];
            const std::size_t next = last ? (closed ? surface[0] : surface[k]) : surface[k + 1];
            const Vec<2> chord = x[next] - x[previous];
            Vec<2> n(-chord.y(), chord.x());
            n.normalize();
            if (n.dot(n0[surface[k]]) < 0.0) n = -n;
            normal[surface[k]] = n;
            const double back = (x[surface[k]] - x[previous]).norm(), ahead = (x[next] - x[surface[k]]).norm();
            spacing[surface[k]] = (previous == surface[k] || next == surface[k]) ? std::max(back, ahead) : 0.5 * (back + ahead);
        }
    }
}

template <int D>
double FluidSystem<D>::smoothingLength() const {
    return std::visit([](const auto& k) { return k.h; }, models_.kernel);
}

template <int D>
Vec<D> FluidSystem<D>::gravityAt(double t) const {
    // Smooth ramp from 0 over gravityRampTime (Adami et al. 2012 hydrostatic test, as in PySPH).
    if (t >= gravityRampTime_) return gravity_;
    return gravity_ * (0.5 * (std::sin((t / gravityRampTime_ - 0.5) * std::numbers::pi) + 1.0));
}

template <int D>
void FluidSystem<D>::sortFluidByCell() {
    auto timer = timers.time(Stage::Neighbours);
    fluid.permute(fluidCells_.cellOrder(fluid.position));
}

template <int D>
void FluidSystem<D>::evaluateRates(double t, RateTerms terms) {
    if (wallsMove_) moveWalls(t);
    {
        auto timer = timers.time(Stage::Neighbours);
        fluidCells_.build(fluid.position);
    }
    {
        auto timer = timers.time(Stage::Density);
        if (!continuity()) computeSummationDensity();
        computeFluidPressure();
    }
    {
        auto timer = timers.time(Stage::Boundary);
        for (Patch<D>& patch : patches)
            if (!patch.cells) patch.model->updateWalls(*this, patch.begin, patch.end, t);
    }
    {
        auto timer = timers.time(Stage::Forces);
        computeForces(gravityAt(t), terms);
    }
    if (terms != RateTerms::ViscousOnly) addWallForces(t);
}

template <int D>
void FluidSystem<D>::addWallForces(double t) {
    auto timer = timers.time(Stage::Boundary);
    if (keepsUncorrectedAcceleration_) fluid.vector("uncorrectedAcceleration") = fluid.vector("acceleration");
    if (fluid.hasVector("boundaryCorrection")) std::fill(fluid.vector("boundaryCorrection").begin(), fluid.vector("boundaryCorrection").end(), Vec<D>::Zero());
    auto& acceleration = fluid.vector("acceleration");
    for (Patch<D>& patch : patches) {
        if (!patch.cells) continue;
        const bool free = patch.motion && patch.motion->isFree();
        std::vector<Vec<D>> before;
        if (free) before = acceleration;
        patch.model->addWallForces(*this, *patch.cells, patch.begin, patch.end, t);
        if (!free) continue;
        // The body takes the reaction of what its patch added to the fluid.
        Vec<D> force = Vec<D>::Zero();
        double torque = 0.0;
        const Vec<D> centreOfMass = patch.motion->centreOfMass();
        const double* m = fluid.scalar("mass").data();
        for (std::size_t i = 0; i < fluid.ownedCount(); ++i) {
            const Vec<D> f = -m[i] * (acceleration[i] - before[i]);
            force += f;
            if constexpr (D == 2) torque += (fluid.position[i] - centreOfMass).x() * f.y() - (fluid.position[i] - centreOfMass).y() * f.x();
        }
        patch.motion->setLoads(force, torque, gravityAt(t), t);
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
void FluidSystem<D>::computeSummationDensity() {
    std::visit(
        [this](const auto& kernel) {
            const std::size_t n = fluid.ownedCount();
            const Vec<D>* x = fluid.position.data();
            const double* mass = fluid.scalar("mass").data();
            const double* wallMass = walls.scalar("mass").data();
            double* rho = fluid.scalar("density").data();
            const double radius = supportRadius_;
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i) {
                double sum = 0.0;
                fluidCells_.forEachNeighbour(x[i], radius, [&](std::uint32_t j, const Vec<D>&, double r2) { sum += mass[j] * kernel.value(std::sqrt(r2)); });
                wallCells_.forEachNeighbour(x[i], radius, [&](std::uint32_t j, const Vec<D>&, double r2) { sum += wallMass[j] * kernel.value(std::sqrt(r2)); });
                rho[i] = sum;
            }
        },
        models_.kernel);
}

template <int D>
void FluidSystem<D>::computeFluidPressure() {
    std::visit(
        [this](const auto& eos) {
            const std::size_t n = fluid.ownedCount();
            const double* rho = fluid.scalar("density").data();
            double* p = fluid.scalar("pressure").data();
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i) p[i] = eos.pressure(rho[i]);
        },
        models_.eos);
}

namespace {

// The hot loop: one instantiation per kernel x viscosity x diffusion x density formulation,
// and per side of an IMEX split (ViscousOnly: the implicit part; the explicit part is the
// instantiation with NoViscosity).
// Disabled terms are compile-time constants and vanish.
template <int D, bool Continuity, bool ViscousOnly, class Kernel, class Viscosity, class Diffusion>
void fluidRates(FluidSystem<D>& s, const Kernel& kernel, const Viscosity& viscosity, const Diffusion& diffusion, const Vec<D>& gravity) {
    constexpr bool Pressure = !ViscousOnly;
    constexpr bool DensityRate = Continuity && !ViscousOnly;
    const std::size_t n = s.fluid.ownedCount();
    const Vec<D>* x = s.fluid.position.data();
    const Vec<D>* v = s.fluid.vector("velocity").data();
    const double* m = s.fluid.scalar("mass").data();
    const double* rho = s.fluid.scalar("density").data();
    const double* p = s.fluid.scalar("pressure").data();
    Vec<D>* a = s.fluid.vector("acceleration").data();
    double* drho = Continuity ? s.fluid.scalar("densityRate").data() : nullptr;
    const Vec<D> bodyForce = Pressure ? gravity : Vec<D>::Zero();
    const Vec<D>* vWall = s.walls.vector("velocity").data();
    const Vec<D>* vWallViscous = Viscosity::enabled ? s.walls.vector("viscousVelocity").data() : nullptr;
    const double* mWall = s.walls.scalar("mass").data();
    const double* rhoWall = s.walls.scalar("density").data();
    const double* pWall = s.walls.scalar("pressure").data();
    const double radius = s.supportRadius();
    const auto& fluidCells = s.fluidCells();
    const auto& wallCells = s.wallCells();

#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        Vec<D> acceleration = bodyForce;
        double densityRate = 0.0;
        [[maybe_unused]] const double pOverRho2 = p[i] / (rho[i] * rho[i]);
        fluidCells.forEachNeighbour(x[i], radius, [&](std::uint32_t j, const Vec<D>& r, double r2) {
            if (j == i) return;
            const double F = kernel.gradientFactor(std::sqrt(r2));
            if constexpr (Pressure) acceleration -= (m[j] * (pOverRho2 + p[j] / (rho[j] * rho[j])) * F) * r;
            const Vec<D> vij = v[i] - v[j];
            if constexpr (DensityRate) densityRate += m[j] * F * vij.dot(r);
            if constexpr (Viscosity::enabled) acceleration += viscosity.acceleration(r, vij, r2, rho[i], rho[j], m[j], F);
            if constexpr (DensityRate && Diffusion::enabled) densityRate += diffusion.rate(r, r2, rho[i], rho[j], m[j], F);
        });
        wallCells.forEachNeighbour(x[i], radius, [&](std::uint32_t k, const Vec<D>& r, double r2) {
            const double F = kernel.gradientFactor(std::sqrt(r2));
            if constexpr (Pressure) acceleration -= (mWall[k] * (pOverRho2 + pWall[k] / (rhoWall[k] * rhoWall[k])) * F) * r;
            if constexpr (DensityRate) densityRate += mWall[k] * F * (v[i] - vWall[k]).dot(r);
            if constexpr (Viscosity::enabled)
                acceleration += viscosity.acceleration(r, Vec<D>(v[i] - vWallViscous[k]), r2, rho[i], rhoWall[k], mWall[k], F);
        });
        a[i] = acceleration;
        if constexpr (Continuity) drho[i] = densityRate;
    }
}

}  // namespace

template <int D>
void FluidSystem<D>::computeForces(const Vec<D>& gravity, RateTerms terms) {
    if (auto* fourtakas = std::get_if<Fourtakas2019<D>>(&models_.diffusion)) fourtakas->gravity = gravity;
    const auto dispatch = [&]<bool ViscousOnly>(const auto& kernel, const auto& viscosity, const auto& diffusion) {
        using Diffusion = std::decay_t<decltype(diffusion)>;
        if (continuity()) {
            fluidRates<D, true, ViscousOnly>(*this, kernel, viscosity, diffusion, gravity);
        } else if constexpr (!Diffusion::enabled) {  // the case reader rejects diffusion with summation density
            fluidRates<D, false, ViscousOnly>(*this, kernel, viscosity, diffusion, gravity);
        }
    };
    std::visit(
        [&](const auto& kernel, const auto& viscosity, const auto& diffusion) {
            using Viscosity = std::decay_t<decltype(viscosity)>;
            if (terms == RateTerms::All) {
                dispatch.template operator()<false>(kernel, viscosity, diffusion);
            } else if constexpr (Viscosity::enabled) {  // without viscosity the split is trivial
                if (terms == RateTerms::AllButViscous) dispatch.template operator()<false>(kernel, NoViscosity{}, diffusion);
                else dispatch.template operator()<true>(kernel, viscosity, NoDensityDiffusion{});
            } else if (terms == RateTerms::AllButViscous) {
                dispatch.template operator()<false>(kernel, viscosity, diffusion);
            } else {
                std::fill(fluid.vector("acceleration").begin(), fluid.vector("acceleration").end(), Vec<D>::Zero());
                if (continuity()) std::fill(fluid.scalar("densityRate").begin(), fluid.scalar("densityRate").end(), 0.0);
            }
        },
        models_.kernel, models_.viscosity, models_.diffusion);
}

template <int D>
bool FluidSystem<D>::viscous() const {
    return std::visit([](const auto& v) { return v.enabled; }, models_.viscosity);
}

template <int D>
double FluidSystem<D>::stableTimeStep(double courant, bool viscousLimit) const {
    const std::size_t n = fluid.ownedCount();
    const Vec<D>* v = fluid.vector("velocity").data();
    const Vec<D>* a = fluid.vector("acceleration").data();
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
