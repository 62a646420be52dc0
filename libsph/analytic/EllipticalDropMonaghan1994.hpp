// Free 2D drop, initially a circle of radius R0 with u = -A0 x, v = A0 y about its centre
// (Monaghan, J. Comput. Phys. 110 (1994) 399). The flow stays linear, u = -A(t) x, v = A(t) y,
// the drop an ellipse with semi-axes a R0 (x) and R0/a (y), where
//   dA/dt = A^2 (a^4 - 1)/(a^4 + 1),  da/dt = -a A,  A(0) = A0, a(0) = 1,
// integrated here with classical RK4 (step 1e-3/A0, cached: times are asked in increasing order).
// Euler's equations then give the pressure, zero on the ellipse:
//   p = p_c (1 - x^2/(a R0)^2 - y^2 a^2/R0^2),  p_c = rho0/2 a^2 R0^2 (A^2 - dA/dt).
//   solution { type ellipticalDrop; A0 100; R0 1; centre (0 0); }
#pragma once

#include "analytic/AnalyticSolution.hpp"

namespace sph {

template <int D>
class EllipticalDropMonaghan1994 : public AnalyticSolution<D> {
public:
    explicit EllipticalDropMonaghan1994(const Dictionary& dict);
    Vec<D> velocity(const Vec<D>& x, double t) const override;
    bool hasPressure() const override { return true; }
    double pressure(const Vec<D>& x, double t, const FlowConstants<D>& constants) const override;

    struct State {
        double rate;   // A
        double ratio;  // a: x semi-axis over R0
    };
    State at(double t) const;

private:
    Vec<D> centre_;
    double initialRate_, radius_;
    mutable double cachedTime_ = 0.0;
    mutable State cached_;
};

}  // namespace sph
