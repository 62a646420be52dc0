// The wall pressure of Adami, Hu & Adams (2012), Eq. 27, extrapolated from the fluid around a
// wall point x_w (the dummy particles' pressure, and the deficiency correction's):
//   p_w = [ sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf ] / sum_f W_wf,   r_wf = x_w - x_f
// The sum over f is the caller's neighbour loop; add() takes one fluid particle.
#pragma once

#include "core/Vector.hpp"

namespace sph {

template <int D>
struct WallPressureExtrapolation {
    double weight = 0.0, pressureSum = 0.0;
    Vec<D> densityMoment = Vec<D>::Zero();

    // W = W(|r_wf|), r = x_w - x_f.
    void add(double W, double pressure, double density, const Vec<D>& r) {
        weight += W;
        pressureSum += pressure * W;
        densityMoment += (density * W) * r;
    }
    // Needs weight > 0; relativeGravity = g - a_w.
    double pressure(const Vec<D>& relativeGravity) const { return (pressureSum + relativeGravity.dot(densityMoment)) / weight; }
};

}  // namespace sph
