// Rigid sinusoidal translation from where the patch was generated:
//   x(t) = x0 + A r(t) [sin(2 pi f t + phase) - sin(phase)]      (phase in radians)
// so the patch never jumps at t = 0; phase pi/2 is the forced surge A cos(2 pi f t) of a
// sloshing tank that starts displaced by A and at rest (Faltinsen et al. 2000). The amplitude
// ramps up over rampTime T_r (default 0: none) as r = tau - sin(2 pi tau)/(2 pi), tau = t/T_r,
// whose first and second derivatives vanish at both ends: the wall starts with no jump in
// position, velocity or acceleration.
// Example (a patch's motion):   motion { type oscillation; amplitude (0.05 0); frequency 0.5; phase 0; rampTime 2; }
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
        : amplitude_(dict.getVector<D>("amplitude")),
          omega_(2.0 * std::numbers::pi * dict.getPositive("frequency")),
          phase_(dict.getOrDefault("phase", 0.0)),
          rampTime_(dict.getNonNegativeOrDefault("rampTime", 0.0)) {}
    std::string describe() const override {
        return fmt::format("oscillation: amplitude ({:g}), frequency {:g}, phase {:g}, rampTime {:g}", fmt::join(amplitude_, " "),
                           omega_ / (2.0 * std::numbers::pi), phase_, rampTime_);
    }
    Kinematics<D> at(const Vec<D>& x0, const Vec<D>&, double t) const override {
        const double angle = omega_ * t + phase_;
        const double s = std::sin(angle) - std::sin(phase_), ds = omega_ * std::cos(angle), dds = -omega_ * omega_ * std::sin(angle);
        if (!(t < rampTime_)) return {x0 + amplitude_ * s, amplitude_ * ds, amplitude_ * dds};
        const double tau = t / rampTime_, turn = 2.0 * std::numbers::pi * tau;
        const double r = tau - std::sin(turn) / (2.0 * std::numbers::pi), dr = (1.0 - std::cos(turn)) / rampTime_,
                     ddr = 2.0 * std::numbers::pi * std::sin(turn) / (rampTime_ * rampTime_);
        return {x0 + amplitude_ * (r * s), amplitude_ * (dr * s + r * ds), amplitude_ * (ddr * s + 2.0 * dr * ds + r * dds)};
    }

private:
    Vec<D> amplitude_;
    double omega_, phase_, rampTime_;
};

}  // namespace sph
