// The decaying 2D Taylor-Green vortex on a periodic square of side L (exact Navier-Stokes
// solution), b = -8 pi^2 nu/L^2:
//   u = -U e^{bt} cos(2 pi x/L) sin(2 pi y/L),  v = U e^{bt} sin(2 pi x/L) cos(2 pi y/L),
//   p = -rho0 U^2 e^{2bt} (cos(4 pi x/L) + cos(4 pi y/L))/4   (up to a constant: WCSPH's
//   background pressure shifts it).
// Taylor & Green, Proc. R. Soc. A 158 (1937) 499; the SPH test as in PySPH's taylor_green example.
//   solution { type taylorGreen; U 1; L 1; nu 0.01; }
#pragma once

#include "analytic/AnalyticSolution.hpp"

namespace sph {

template <int D>
class TaylorGreen2D : public AnalyticSolution<D> {
public:
    explicit TaylorGreen2D(const Dictionary& dict);
    Vec<D> velocity(const Vec<D>& x, double t) const override;
    bool hasPressure() const override { return true; }
    double pressure(const Vec<D>& x, double t, const FlowConstants<D>& constants) const override;

private:
    double speed_, side_, decayRate_;
};

}  // namespace sph
