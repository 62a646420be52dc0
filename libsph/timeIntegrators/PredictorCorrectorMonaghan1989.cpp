#include "timeIntegrators/PredictorCorrectorMonaghan1989.hpp"

#include "timeIntegrators/EvolvedState.hpp"

namespace sph {

namespace {

// y^{n+1} = 2 y^{n+1/2} - y^n
template <class T>
void extrapolate(std::vector<T>& y, const std::vector<T>& start, std::size_t n) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) y[i] = 2.0 * y[i] - start[i];
}

}  // namespace

template <int D>
double PredictorCorrectorMonaghan1989<D>::takeStep(IntegrableSystem<D>& system, double t, double dt) {
    auto& fluid = system.fluid;
    const std::size_t n = fluid.ownedCount();
    auto& x = fluid.position;
    auto& v = fluid[fields::velocity];
    const auto& a = fluid[fields::acceleration];
    const auto densitySets = evolvedDensitySets(system);
    const double halfDt = 0.5 * dt;
    // y^{n+1/2} = y^n + dt/2 f(current rates); the positions take the velocity before it
    // changes in the predictor (v^n) and after it in the corrector (v^{n+1/2}).
    const auto halfStep = [&](bool positionsFirst) {
        if (positionsFirst) addScaled(x, start_.position, halfDt, v, n);
        addScaled(v, start_.velocity, halfDt, a, n);
        if (!positionsFirst) addScaled(x, start_.position, halfDt, v, n);
        for (std::size_t s = 0; s < densitySets.size(); ++s)
            addScaled((*densitySets[s])[fields::density], start_.density[s], halfDt, (*densitySets[s])[fields::densityRate],
                      densitySets[s]->ownedCount());
    };
    {
        auto timer = system.timers.time(Stage::Integrator);
        start_.save(system, densitySets);
        halfStep(true);
    }
    this->evaluate(system, t + halfDt);
    {
        auto timer = system.timers.time(Stage::Integrator);
        halfStep(false);
        extrapolate(x, start_.position, n);
        extrapolate(v, start_.velocity, n);
        for (std::size_t s = 0; s < densitySets.size(); ++s)
            extrapolate((*densitySets[s])[fields::density], start_.density[s], densitySets[s]->ownedCount());
    }
    this->evaluateAtStepEnd(system, t + dt);
    return dt;
}

template class PredictorCorrectorMonaghan1989<1>;
template class PredictorCorrectorMonaghan1989<2>;
template class PredictorCorrectorMonaghan1989<3>;

}  // namespace sph
