// Rigid rotation in 2D about a fixed centre, by the angle
//   theta(t) = omega t + amplitude sin(2 pi f t)
// (constant rate, sinusoidal roll, or both); normals turn with the patch.
// Example (a patch's motion):   motion { type rotation; centre (0.5 0.3); omega 0; amplitude 0.1; frequency 0.5; }
#pragma once

#include "motion/PatchMotion.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace sph {

class Rotation : public PatchMotion<2> {
public:
    explicit Rotation(const Dictionary& dict)
        : centre_(dict.getVector<2>("centre")),
          omega_(dict.getOrDefault("omega", 0.0)),
          amplitude_(dict.getOrDefault("amplitude", 0.0)),
          angularFrequency_(2.0 * std::numbers::pi * dict.getNonNegativeOrDefault("frequency", 0.0)) {}
    std::string describe() const override {
        return fmt::format("rotation: centre ({:g}), omega {:g}, amplitude {:g}, frequency {:g}", fmt::join(centre_, " "), omega_, amplitude_,
                           angularFrequency_ / (2.0 * std::numbers::pi));
    }
    Kinematics<2> at(const Vec<2>& x0, const Vec<2>&, double t) const override {
        const double theta = omega_ * t + amplitude_ * std::sin(angularFrequency_ * t);
        const double rate = omega_ + amplitude_ * angularFrequency_ * std::cos(angularFrequency_ * t);
        const double rateChange = -amplitude_ * angularFrequency_ * angularFrequency_ * std::sin(angularFrequency_ * t);
        const Vec<2> arm = rotate(x0 - centre_, theta);
        const Vec<2> perpendicular(-arm.y(), arm.x());
        return {centre_ + arm, rate * perpendicular, rateChange * perpendicular - rate * rate * arm};
    }
    Vec<2> normalAt(const Vec<2>& n0, double t) const override { return rotate(n0, omega_ * t + amplitude_ * std::sin(angularFrequency_ * t)); }

private:
    static Vec<2> rotate(const Vec<2>& v, double angle) {
        return {std::cos(angle) * v.x() - std::sin(angle) * v.y(), std::sin(angle) * v.x() + std::cos(angle) * v.y()};
    }
    Vec<2> centre_;
    double omega_, amplitude_, angularFrequency_;
};

}  // namespace sph
