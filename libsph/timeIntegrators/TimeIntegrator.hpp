// The time-integrator family. An integrator advances the FluidSystem's state (fluid position,
// velocity, density with continuity, and wall density where a boundary model evolves it)
// by one step, calling evaluateRates() for the right-hand side. On entry the rates at the
// start of the step are current; on exit they must be current at its end.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"

#include <memory>
#include <string>

namespace sph {

template <int D>
class FluidSystem;

template <int D>
class TimeIntegrator {
public:
    virtual ~TimeIntegrator() = default;
    virtual std::string describe() const = 0;
    virtual void step(FluidSystem<D>& system, double t, double dt) = 0;
    std::size_t rateEvaluations() const { return evaluations_; }

protected:
    void evaluate(FluidSystem<D>& system, double t);

private:
    std::size_t evaluations_ = 0;
};

template <int D>
using TimeIntegratorRegistry = Registry<std::unique_ptr<TimeIntegrator<D>>, const Dictionary&>;

template <int D>
TimeIntegratorRegistry<D> makeTimeIntegratorRegistry();

}  // namespace sph
