// A surface that slides along itself: the particles keep their places and carry the velocity U,
// as a lid driven over a cavity or a conveyor belt. No-slip wall models then drag the fluid at U
// while the wall never moves away. U must be tangential at every particle (U . n0 = 0): a normal
// component would be a velocity the wall's position does not follow, and is an error.
// Example (a patch's motion):   motion { type slidingSurface; velocity (1 0); }
#pragma once

#include "core/FatalError.hpp"
#include "motion/PatchMotion.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

template <int D>
class SlidingSurface : public PatchMotion<D> {
public:
    explicit SlidingSurface(const Dictionary& dict) : velocity_(dict.getVector<D>("velocity")), where_(dict.entry("velocity").where()) {}
    std::string describe() const override { return fmt::format("slidingSurface: velocity ({:g}) along the surface", fmt::join(velocity_, " ")); }
    Kinematics<D> at(const Vec<D>& x0, const Vec<D>& n0, double) const override {
        if (std::abs(velocity_.dot(n0)) > 1e-9 * velocity_.norm())
            throw FatalError(where_, fmt::format("slidingSurface velocity ({:g}) is not tangential to the wall at ({:g}), normal ({:g})",
                                                 fmt::join(velocity_, " "), fmt::join(x0, " "), fmt::join(n0, " ")));
        return {x0, velocity_, Vec<D>::Zero()};
    }

private:
    Vec<D> velocity_;
    SourceLocation where_;
};

}  // namespace sph
