// The body force of a case, ramped smoothly from zero over rampTime where the case asks (the
// hydrostatic test of Adami et al. 2012, as PySPH runs it):
//   g(t) = g (1 + sin(pi (t / T - 1/2))) / 2   for t < T,   g after.
// Example (constant/fluidProperties):   gravity (0 -9.81); gravityRampTime 0.5;
#pragma once

#include "core/Vector.hpp"

#include <cmath>
#include <numbers>

namespace sph {

template <int D>
struct Gravity {
    Vec<D> full = Vec<D>::Zero();  // after the ramp: its direction is down
    double rampTime = 0.0;

    Vec<D> at(double t) const {
        if (t >= rampTime) return full;
        return full * (0.5 * (std::sin((t / rampTime - 0.5) * std::numbers::pi) + 1.0));
    }
};

}  // namespace sph
