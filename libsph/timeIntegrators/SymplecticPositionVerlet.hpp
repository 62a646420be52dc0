// Symplectic position-Verlet predictor-corrector, second order, as in DualSPHysics:
//   predictor:  x* = x^n + dt/2 v^n,  v* = v^n + dt/2 a^n,  rho* = rho^n + dt/2 drho^n
//   rates at t + dt/2 from the predicted state
//   corrector:  v^{n+1} = v^n + dt a*,  x^{n+1} = x^n + dt/2 (v^n + v^{n+1}),
//               rho^{n+1} = rho^n (2 - eps)/(2 + eps),  eps = -(drho*/rho*) dt
//   rates at t + dt (they start the next step)
// Two right-hand-side evaluations per step.
// Reference: B.J. Leimkuhler, S. Reich, R.D. Skeel (1996); J.M. Dominguez et al.,
// Comput. Phys. Commun. 262 (2021) 107-157 (DualSPHysics v5), Sec. 2.6.
// Example (system/timeIntegration):   integrator { type symplectic; }
#pragma once

#include "timeIntegrators/EvolvedState.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

namespace sph {

template <int D>
class SymplecticPositionVerlet : public TimeIntegrator<D> {
public:
    std::string describe() const override { return "symplectic (position Verlet predictor-corrector)"; }
    bool advancesFreeBodies() const override { return true; }

protected:
    double takeStep(IntegrableSystem<D>& system, double t, double dt) override;

private:
    StepStart<D> start_;
};

}  // namespace sph
