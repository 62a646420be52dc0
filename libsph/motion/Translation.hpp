// Rigid translation at constant velocity:  x(t) = x0 + U t.
// Example (a patch's motion):   motion { type translation; velocity (0.1 0); }
#pragma once

#include "motion/PatchMotion.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
class Translation : public PatchMotion<D> {
public:
    explicit Translation(const Dictionary& dict) : velocity_(dict.getVector<D>("velocity")) {}
    std::string describe() const override { return fmt::format("translation: velocity ({:g})", fmt::join(velocity_, " ")); }
    Kinematics<D> at(const Vec<D>& x0, const Vec<D>&, double t) const override { return {x0 + velocity_ * t, velocity_, Vec<D>::Zero()}; }

private:
    Vec<D> velocity_;
};

}  // namespace sph
