// Start-up flows between plates y = 0 and y = L (Morris, Fox & Zhu, J. Comput. Phys. 136 (1997)
// 214, Sec. 4), fluid at rest at t = 0, velocity along x:
//   poiseuille (body force F along x, both plates at rest):
//     u(y,t) = F/(2 nu) y (L - y) - sum_{n>=0} 4 F L^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y/L) exp(-(2n+1)^2 pi^2 nu t/L^2)
//   couette (upper plate moved impulsively at V0):
//     u(y,t) = V0 y/L + sum_{n>=1} 2 V0/(n pi) (-1)^n sin(n pi y/L) exp(-n^2 pi^2 nu t/L^2)
// The series are summed until a term falls below 1e-16 of the steady velocity (at most 10,000 terms).
//   solution { type poiseuille; F 2e-4; L 1e-3; nu 1e-6; }
//   solution { type couette; V0 2.5e-5; L 1e-3; nu 1e-6; }
#pragma once

#include "analytic/AnalyticSolution.hpp"

namespace sph {

template <int D>
class PoiseuilleMorris1997 : public AnalyticSolution<D> {
public:
    explicit PoiseuilleMorris1997(const Dictionary& dict);
    Vec<D> velocity(const Vec<D>& x, double t) const override;

private:
    double force_, width_, nu_;
};

template <int D>
class CouetteMorris1997 : public AnalyticSolution<D> {
public:
    explicit CouetteMorris1997(const Dictionary& dict);
    Vec<D> velocity(const Vec<D>& x, double t) const override;

private:
    double plateVelocity_, width_, nu_;
};

}  // namespace sph
