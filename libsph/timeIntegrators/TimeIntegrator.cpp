#include "timeIntegrators/TimeIntegrator.hpp"

#include "physics/FluidSystem.hpp"
#include "timeIntegrators/SymplecticPositionVerlet.hpp"

namespace sph {

template <int D>
void TimeIntegrator<D>::evaluate(FluidSystem<D>& system, double t) {
    ++evaluations_;
    system.evaluateRates(t);
}

template <int D>
TimeIntegratorRegistry<D> makeTimeIntegratorRegistry() {
    TimeIntegratorRegistry<D> registry("time integrator");
    registry.add("symplectic", {"symplectic position-Verlet predictor-corrector, 2 evaluations per step", "Dominguez et al., Comput. Phys. Commun. 262 (2021)", {}},
                 [](const Dictionary&) -> std::unique_ptr<TimeIntegrator<D>> { return std::make_unique<SymplecticPositionVerlet<D>>(); });
    return registry;
}

template class TimeIntegrator<1>;
template class TimeIntegrator<2>;
template class TimeIntegrator<3>;
template TimeIntegratorRegistry<1> makeTimeIntegratorRegistry<1>();
template TimeIntegratorRegistry<2> makeTimeIntegratorRegistry<2>();
template TimeIntegratorRegistry<3> makeTimeIntegratorRegistry<3>();

}  // namespace sph
