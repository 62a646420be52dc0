// Rigid sinusoidal translation from where the patch was generated:
//   x(t) = x0 + A [sin(2 pi f t + phase) - sin(phase)]      (phase in radians)
// so the patch never jumps at t = 0; phase pi/2 is the forced surge A cos(2 pi f t) of a
// sloshing tank that starts displaced by A and at rest (Faltinsen et al. 2000).
// Example (a patch's motion):   motion { type oscillation; amplitude (0.05 0); frequency 0.5; phase 0; }
#pragma once

#include "motion/PatchMotion.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace sph {

template <int D>
class Oscillation : public PatchMotion<D> {
public:
    explicit Oscillation(const Dictionary& dict)
        : amplitude_(dict.getVector<D>("amplitude")), omega_(2.0 * std::numbers::pi * dict.getPositive("frequency")),
          phase_(dict.getOrDefault("phase", 0.0)) {}
    std::string describe() const override {
        return fmt::format("oscillation: amplitude ({:g}), frequency {:g}, phase {:g}", fmt::join(amplitude_, " "), omega_ / (2.0 * std::numbers::pi), phase_);
    }
    Kinematics<D> at(const Vec<D>& x0, const Vec<D>&, double t) const override {
        const double angle = omega_ * t + phase_;
        return {x0 + amplitude_ * (std::sin(angle) - std::sin(phase_)), amplitude_ * (omega_ * std::cos(angle)), amplitude_ * (-omega_ * omega_ * std::sin(angle))};
    }

private:
    Vec<D> amplitude_;
    double omega_, phase_;
};

}  // namespace sph
