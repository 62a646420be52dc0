#include "timeIntegrators/VerletMonaghan1994.hpp"

#include "timeIntegrators/EvolvedState.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
std::string VerletMonaghan1994<D>::describe() const {
    return fmt::format("verlet (Euler step every {} steps)", eulerEvery_);
}

template <int D>
void VerletMonaghan1994<D>::resume(const IntegrableSystem<D>& system, const std::vector<double>& saved) {
    // Without the previous level (a state from another integrator) the next step is an Euler step.
    const bool previousLevelWritten = system.fluid.has(fields::previousVelocity) &&
                                      (!system.continuity() || system.fluid.has(fields::previousDensity)) &&
                                      (!system.wallDensityEvolves() || system.walls.has(fields::previousDensity));
    if (saved.size() == 1 && previousLevelWritten && saved[0] >= -1.0 && saved[0] < eulerEvery_) stepsSinceEuler_ = static_cast<int>(saved[0]);
}

template <int D>
double VerletMonaghan1994<D>::takeStep(IntegrableSystem<D>& system, double t, double dt) {
    {
        auto timer = system.timers.time(Stage::Integrator);
        const bool euler = stepsSinceEuler_ < 0 || stepsSinceEuler_ + 1 >= eulerEvery_;
        stepsSinceEuler_ = euler ? 0 : stepsSinceEuler_ + 1;
        // An Euler step reads the current level twice: v^{n+1} = v^n + dt a^n.
        const double reach = euler ? dt : 2.0 * dt;
        auto& fluid = system.fluid;
        const std::size_t n = fluid.ownedCount();
        auto& x = fluid.position;
        auto& v = fluid[fields::velocity];
        const auto& a = fluid[fields::acceleration];
        auto& vPrevious = fluid.add(fields::previousVelocity, Vec<D>::Zero());
        const double halfDt2 = 0.5 * dt * dt;
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
            x[i] += dt * v[i] + halfDt2 * a[i];
            const Vec<D> older = euler ? v[i] : vPrevious[i];
            vPrevious[i] = v[i];
            v[i] = older + reach * a[i];
        }
        for (ParticleSet<D>* set : evolvedDensitySets(system)) {
            auto& rho = (*set)[fields::density];
            auto& rhoPrevious = set->add(fields::previousDensity, 0.0);
            const auto& rate = (*set)[fields::densityRate];
            const std::size_t count = set->ownedCount();
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < count; ++i) {
                const double older = euler ? rho[i] : rhoPrevious[i];
                rhoPrevious[i] = rho[i];
                rho[i] = older + reach * rate[i];
            }
        }
    }
    this->evaluateAtStepEnd(system, t + dt);
    return dt;
}

template class VerletMonaghan1994<1>;
template class VerletMonaghan1994<2>;
template class VerletMonaghan1994<3>;

}  // namespace sph
