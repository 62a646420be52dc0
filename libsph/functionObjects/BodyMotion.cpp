#include "functionObjects/BodyMotion.hpp"

#include "motion/FreeBody2D.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
BodyMotion<D>::BodyMotion(const Dictionary& dict, const FunctionObjectContext<D>& context) : patch_(dict.get<std::string>("patch")), dict_(&dict) {
    if constexpr (D != 2) dict.fail("type", "bodyMotion reports 2D free bodies only");
    out_ = context.series("body.dat", "# t X Y angle Vx Vy omega Fx Fy torque");
}

template <int D>
void BodyMotion<D>::execute(const FluidSystemView<D>& system, double t) {
    if constexpr (D == 2) {
        const FreeBody2D* body = nullptr;
        for (const Patch<D>& patch : system.patches)
            if (patch.name == patch_) body = dynamic_cast<const FreeBody2D*>(patch.motion.get());
        if (!body) dict_->fail("patch", "'" + patch_ + "' is not a patch whose motion is freeBody");
        const auto& s = body->state();
        out_.append(fmt::format("{:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g}", t, s.position.x(), s.position.y(), s.angle,
                                s.velocity.x(), s.velocity.y(), s.angularVelocity, body->force().x(), body->force().y(), body->torque()));
    }
}

template class BodyMotion<1>;
template class BodyMotion<2>;
template class BodyMotion<3>;

}  // namespace sph
