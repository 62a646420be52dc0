#include "timeIntegrators/LeapfrogKickDriftKick.hpp"

#include "timeIntegrators/EvolvedState.hpp"

namespace sph {

template <int D>
double LeapfrogKickDriftKick<D>::takeStep(IntegrableSystem<D>& system, double t, double dt) {
    auto& fluid = system.fluid;
    const std::size_t n = fluid.ownedCount();
    auto& v = fluid[fields::velocity];
    const auto& a = fluid[fields::acceleration];
    const auto densitySets = evolvedDensitySets(system);
    const double halfDt = 0.5 * dt;
    {
        auto timer = system.timers.time(Stage::Integrator);
        halfStepVelocity_.resize(n);
        addScaled(halfStepVelocity_, v, halfDt, a, n);
        addScaled(fluid.position, fluid.position, dt, halfStepVelocity_, n);
        addScaled(v, halfStepVelocity_, halfDt, a, n);  // predicted to the end of the step
        halfStepDensity_.resize(densitySets.size());
        for (std::size_t s = 0; s < densitySets.size(); ++s) {
            auto& rho = (*densitySets[s])[fields::density];
            const auto& rate = (*densitySets[s])[fields::densityRate];
            const std::size_t count = densitySets[s]->ownedCount();
            halfStepDensity_[s].resize(count);
            addScaled(halfStepDensity_[s], rho, halfDt, rate, count);
            addScaled(rho, halfStepDensity_[s], halfDt, rate, count);
        }
    }
    this->evaluate(system, t + dt);
    auto timer = system.timers.time(Stage::Integrator);
    addScaled(v, halfStepVelocity_, halfDt, a, n);
    for (std::size_t s = 0; s < densitySets.size(); ++s)
        addScaled((*densitySets[s])[fields::density], halfStepDensity_[s], halfDt, (*densitySets[s])[fields::densityRate],
                  densitySets[s]->ownedCount());
    return dt;
}

template class LeapfrogKickDriftKick<1>;
template class LeapfrogKickDriftKick<2>;
template class LeapfrogKickDriftKick<3>;

}  // namespace sph
