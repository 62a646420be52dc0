// Still water under gravity: u = 0, p = rho0 |g(t)| (H - z), z measured against gravity and H
// the free-surface height (g(t) follows the case's gravity ramp).
//   solution { type hydrostatic; freeSurfaceHeight 0.9; }
#pragma once

#include "analytic/AnalyticSolution.hpp"

namespace sph {

template <int D>
class HydrostaticPressure : public AnalyticSolution<D> {
public:
    explicit HydrostaticPressure(const Dictionary& dict) : freeSurfaceHeight_(dict.get<double>("freeSurfaceHeight")) {}
    double freeSurfaceHeight() const { return freeSurfaceHeight_; }
    Vec<D> velocity(const Vec<D>&, double) const override { return Vec<D>::Zero(); }
    bool hasPressure() const override { return true; }
    double pressure(const Vec<D>& x, double, const FlowConstants<D>& constants) const override {
        const double g = constants.gravity.norm();
        const double height = g > 0.0 ? -x.dot(constants.gravity) / g : 0.0;
        return constants.rho0 * g * (freeSurfaceHeight_ - height);
    }

private:
    double freeSurfaceHeight_;
};

}  // namespace sph
