// Verlet scheme with an Euler step every N steps, one right-hand-side evaluation per step:
//   x^{n+1}   = x^n + dt v^n + dt^2/2 a^n
//   v^{n+1}   = v^{n-1} + 2 dt a^n            (Euler step: v^n + dt a^n)
//   rho^{n+1} = rho^{n-1} + 2 dt drho^n       (Euler step: rho^n + dt drho^n)
// The Euler step every N steps (and the first) couples the two leapfrog sequences of the
// three-level scheme, which would otherwise drift apart. The previous velocity and density
// are particle fields, so reordering by cell keeps them with their particles, and they are
// written with the state: a restart continues the three-level sequence where it stopped.
// References: J.J. Monaghan, J. Comput. Phys. 110 (1994) 399-406; A.J.C. Crespo et al.,
// Comput. Phys. Commun. 187 (2015) 204-216 (DualSPHysics, "Verlet", VerletSteps = 40).
// Example (system/timeIntegration):   integrator { type verlet; eulerEvery 40; }
#pragma once

#include "timeIntegrators/TimeIntegrator.hpp"

namespace sph {

template <int D>
class VerletMonaghan1994 : public TimeIntegrator<D> {
public:
    explicit VerletMonaghan1994(int eulerEvery) : eulerEvery_(eulerEvery) {}
    std::string describe() const override;
    std::vector<double> savedState() const override { return {static_cast<double>(stepsSinceEuler_)}; }
    void resume(const IntegrableSystem<D>& system, const std::vector<double>& saved) override;

protected:
    double takeStep(IntegrableSystem<D>& system, double t, double dt) override;

private:
    int eulerEvery_;
    int stepsSinceEuler_ = -1;  // -1: the first step is an Euler step
};

}  // namespace sph
