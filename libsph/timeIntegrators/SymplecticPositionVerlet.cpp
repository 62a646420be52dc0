#include "timeIntegrators/SymplecticPositionVerlet.hpp"

#include "physics/FluidSystem.hpp"

namespace sph {

namespace {

// rho^{n+1} = rho^n (2 - eps)/(2 + eps), eps = -(drho*/rho*) dt: exact for a constant
// relative rate, and keeps the density positive.
void correctDensity(std::vector<double>& rho, const std::vector<double>& rhoStart, const std::vector<double>& rate, double dt, std::size_t n) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        const double eps = -rate[i] / rho[i] * dt;
        rho[i] = rhoStart[i] * (2.0 - eps) / (2.0 + eps);
    }
}

void predictDensity(std::vector<double>& rho, const std::vector<double>& rate, double halfDt, std::size_t n) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) rho[i] += halfDt * rate[i];
}

}  // namespace

template <int D>
void SymplecticPositionVerlet<D>::step(FluidSystem<D>& system, double t, double dt) {
    auto& fluid = system.fluid;
    const std::size_t n = fluid.ownedCount();
    auto& x = fluid.position;
    auto& v = fluid.vector("velocity");
    const auto& a = fluid.vector("acceleration");
    const double halfDt = 0.5 * dt;
    {
        auto timer = system.timers.time(Stage::Integrator);
        x0_ = x;
        v0_ = v;
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
            x[i] += halfDt * v[i];
            v[i] += halfDt * a[i];
        }
        if (system.continuity()) {
            rho0_ = fluid.scalar("density");
            predictDensity(fluid.scalar("density"), fluid.scalar("densityRate"), halfDt, n);
        }
        system.predictBodies(halfDt);
        if (system.wallDensityEvolves()) {
            wallRho0_ = system.walls.scalar("density");
            predictDensity(system.walls.scalar("density"), system.walls.scalar("densityRate"), halfDt, system.walls.ownedCount());
        }
    }
    this->evaluate(system, t + halfDt);
    {
        auto timer = system.timers.time(Stage::Integrator);
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
            v[i] = v0_[i] + dt * a[i];
            x[i] = x0_[i] + halfDt * (v0_[i] + v[i]);
        }
        if (system.continuity()) correctDensity(fluid.scalar("density"), rho0_, fluid.scalar("densityRate"), dt, n);
        system.correctBodies(dt);
        if (system.wallDensityEvolves())
            correctDensity(system.walls.scalar("density"), wallRho0_, system.walls.scalar("densityRate"), dt, system.walls.ownedCount());
    }
    this->evaluate(system, t + dt);
}

template class SymplecticPositionVerlet<1>;
template class SymplecticPositionVerlet<2>;
template class SymplecticPositionVerlet<3>;

}  // namespace sph
