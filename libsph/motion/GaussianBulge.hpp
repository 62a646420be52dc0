// Prescribed deformation: a Gaussian bulge of the wall along its initial normal n0,
//   x(t) = x0 + A(t) exp(-|x0 - c|^2 / w^2) n0,     A(t) = amplitude sin(2 pi t / period)
// so the bulge grows convex (into the fluid) over the first quarter period, returns, and turns
// concave over the second half (the situation of the paper's Fig. 4). Every layer of wall
// particles moves by the field at its own initial position, so virtual particles behind the
// wall bunch or spread as the paper describes. Normals and areas follow Nanson's formula
// (areaStretch) where the wall is not a 2D curve, whose moved surface gives them.
// Example (a patch's motion):   motion { type gaussianBulge; centre (1 0); amplitude 0.1; width 0.2; period 2; }
#pragma once

#include "motion/PatchMotion.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace sph {

template <int D>
class GaussianBulge : public PatchMotion<D> {
public:
    explicit GaussianBulge(const Dictionary& dict)
        : centre_(dict.getVector<D>("centre")),
          amplitude_(dict.get<double>("amplitude")),
          width_(dict.getPositive("width")),
          omega_(2.0 * std::numbers::pi / dict.getPositive("period")) {}
    std::string describe() const override {
        return fmt::format("gaussianBulge: centre ({:g}), amplitude {:g}, width {:g}, period {:g}", fmt::join(centre_, " "), amplitude_, width_,
                           2.0 * std::numbers::pi / omega_);
    }
    bool deforms() const override { return true; }
    Kinematics<D> at(const Vec<D>& x0, const Vec<D>& n0, double t) const override {
        const Vec<D> shape = n0 * (amplitude_ * std::exp(-(x0 - centre_).squaredNorm() / (width_ * width_)));
        return {x0 + shape * std::sin(omega_ * t), shape * (omega_ * std::cos(omega_ * t)), shape * (-omega_ * omega_ * std::sin(omega_ * t))};
    }

    // u = A(t) e(x0) n0 with n0 constant along a flat wall: F = I + A(t) n0 (grad e)^T, so
    // J F^-T n0 = (1 + A(t) grad e . n0) n0 - A(t) grad e (on a curved wall the term A e grad n0
    // is left out).
    Vec<D> areaStretch(const Vec<D>& x0, const Vec<D>& n0, double t) const override {
        const double lift = amplitude_ * std::sin(omega_ * t);
        const Vec<D> gradient = (x0 - centre_) * (-2.0 / (width_ * width_) * std::exp(-(x0 - centre_).squaredNorm() / (width_ * width_)));
        return (1.0 + lift * gradient.dot(n0)) * n0 - lift * gradient;
    }

private:
    Vec<D> centre_;
    double amplitude_, width_, omega_;
};

}  // namespace sph
