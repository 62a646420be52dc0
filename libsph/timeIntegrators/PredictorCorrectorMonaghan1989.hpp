// Predictor-corrector, two right-hand-side evaluations per step, second order:
//   predictor:  y* = y^n + dt/2 f(y^n)               for y = (x, v, rho)
//   corrector:  y^{n+1/2} = y^n + dt/2 f(y*)
//   step:       y^{n+1} = 2 y^{n+1/2} - y^n,   then the rates at t + dt
// (the positions use the corrected velocities: x^{n+1} = x^n + dt v^{n+1/2}).
// References: J.J. Monaghan, J. Comput. Phys. 82 (1989) 1-15; M. Gomez-Gesteira et al.,
// J. Hydraul. Res. 48 (2010) 6-27 (SPHysics, Sec. 3.1).
// Example (system/timeIntegration):   integrator { type predictorCorrector; }
#pragma once

#include "timeIntegrators/EvolvedState.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

namespace sph {

template <int D>
class PredictorCorrectorMonaghan1989 : public TimeIntegrator<D> {
public:
    std::string describe() const override { return "predictorCorrector (Monaghan 1989)"; }

protected:
    double takeStep(IntegrableSystem<D>& system, double t, double dt) override;

private:
    StepStart<D> start_;
};

}  // namespace sph
