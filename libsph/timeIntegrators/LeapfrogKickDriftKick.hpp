// Kick-drift-kick leapfrog, one right-hand-side evaluation per step, second order:
//   v^{n+1/2} = v^n + dt/2 a^n,       rho^{n+1/2} = rho^n + dt/2 drho^n      (kick)
//   x^{n+1}   = x^n + dt v^{n+1/2}                                          (drift)
//   rates at (x^{n+1}, v^n + dt a^n, rho^n + dt drho^n)
//   v^{n+1}   = v^{n+1/2} + dt/2 a^{n+1},  rho^{n+1} = rho^{n+1/2} + dt/2 drho^{n+1}   (kick)
// Viscosity depends on velocity and pressure on density, so the evaluation takes velocity and
// density predicted to the end of the step, as Springel does for SPH; evaluating them at the
// half step instead lags them by dt/2 and makes the scheme first order. The rates a step ends
// with are those of the predicted state; a restart takes them from the written state file.
// Reference: V. Springel, Mon. Not. R. Astron. Soc. 364 (2005) 1105-1134, Sec. 4.
// Example (system/timeIntegration):   integrator { type leapfrog; }
#pragma once

#include "core/Vector.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <vector>

namespace sph {

template <int D>
class LeapfrogKickDriftKick : public TimeIntegrator<D> {
public:
    std::string describe() const override { return "leapfrog (kick-drift-kick)"; }
    bool carriesPredictedRates() const override { return true; }

protected:
    double takeStep(IntegrableSystem<D>& system, double t, double dt) override;

private:
    std::vector<Vec<D>> halfStepVelocity_;
    std::vector<std::vector<double>> halfStepDensity_;  // per evolved density set
};

}  // namespace sph
