#include "timeIntegrators/SymplecticPositionVerlet.hpp"

#include "timeIntegrators/IntegrableSystem.hpp"
#include "timeIntegrators/EvolvedState.hpp"

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

}  // namespace

template <int D>
double SymplecticPositionVerlet<D>::takeStep(IntegrableSystem<D>& system, double t, double dt) {
    auto& fluid = system.fluid;
    const std::size_t n = fluid.ownedCount();
    auto& x = fluid.position;
    auto& v = fluid[fields::velocity];
    const auto& a = fluid[fields::acceleration];
    const auto densitySets = evolvedDensitySets(system);
    const double halfDt = 0.5 * dt;
    {
        auto timer = system.timers.time(Stage::Integrator);
        start_.save(system, densitySets);
        addScaled(x, x, halfDt, v, n);
        addScaled(v, v, halfDt, a, n);
        for (ParticleSet<D>* set : densitySets)
            addScaled((*set)[fields::density], (*set)[fields::density], halfDt, (*set)[fields::densityRate], set->ownedCount());
        system.predictBodies(halfDt);
    }
    this->evaluate(system, t + halfDt);
    {
        auto timer = system.timers.time(Stage::Integrator);
        addScaled(v, start_.velocity, dt, a, n);
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) x[i] = start_.position[i] + halfDt * (start_.velocity[i] + v[i]);
        for (std::size_t s = 0; s < densitySets.size(); ++s)
            correctDensity((*densitySets[s])[fields::density], start_.density[s], (*densitySets[s])[fields::densityRate], dt,
                           densitySets[s]->ownedCount());
        system.correctBodies(dt);
    }
    this->evaluateAtStepEnd(system, t + dt);
    return dt;
}

template class SymplecticPositionVerlet<1>;
template class SymplecticPositionVerlet<2>;
template class SymplecticPositionVerlet<3>;

}  // namespace sph
