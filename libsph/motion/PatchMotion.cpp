#include "motion/PatchMotion.hpp"

#include "motion/FreeBody2D.hpp"
#include "motion/GaussianBulge.hpp"
#include "motion/MotionTable.hpp"
#include "motion/Oscillation.hpp"
#include "motion/Rotation.hpp"
#include "motion/SlidingSurface.hpp"
#include "motion/Translation.hpp"

namespace sph {

template <int D>
PatchMotionRegistry<D> makePatchMotionRegistry() {
    using Made = std::unique_ptr<PatchMotion<D>>;
    PatchMotionRegistry<D> registry("motion");
    registry.add("translation", {"rigid, constant velocity", "", {{"velocity", "", "U"}}},
                 [](const Dictionary& dict, const std::string&) -> Made { return std::make_unique<Translation<D>>(dict); });
    registry.add("slidingSurface",
                 {"the surface slides along itself: particles stay, carry U (a driven lid)", "", {{"velocity", "", "U, tangential"}}},
                 [](const Dictionary& dict, const std::string&) -> Made { return std::make_unique<SlidingSurface<D>>(dict); });
    registry.add("oscillation",
                 {"rigid, x0 + A r(t) [sin(2 pi f t + phase) - sin(phase)]",
                  "",
                  {{"amplitude", "", "A"},
                   {"frequency", "", "f [Hz]"},
                   {"phase", "0", "[rad]; pi/2: A cos(2 pi f t) about x0 + A, from rest"},
                   {"rampTime", "0", "T_r [s]: r = tau - sin(2 pi tau)/(2 pi), tau = t/T_r, then 1"}}},
                 [](const Dictionary& dict, const std::string&) -> Made { return std::make_unique<Oscillation<D>>(dict); });
    registry.add("rotation",
                 {"rigid 2D rotation, theta = omega t + amplitude sin(2 pi f t)",
                  "",
                  {{"centre", "", "the axis (x y)"}, {"omega", "0", "[rad/s]"}, {"amplitude", "0", "[rad]"}, {"frequency", "0", "[Hz]"}}},
                 [](const Dictionary& dict, const std::string&) -> Made {
                     if constexpr (D == 2) return std::make_unique<Rotation>(dict);
                     dict.fail("type", "rotation is implemented for 2D cases only");
                 });
    registry.add("gaussianBulge",
                 {"deformation A sin(2 pi t/T) exp(-|x0 - c|^2/w^2) n0",
                  "",
                  {{"centre", "", "c"}, {"amplitude", "", "A (> 0: convex first)"}, {"width", "", "w"}, {"period", "", "T"}}},
                 [](const Dictionary& dict, const std::string&) -> Made { return std::make_unique<GaussianBulge<D>>(dict); });
    registry.add(
        "table", {"rigid translation interpolated from a file of rows t dx dy [dz]", "", {{"file", "", "relative to the case"}}},
        [](const Dictionary& dict, const std::string& caseDirectory) -> Made { return std::make_unique<MotionTable<D>>(dict, caseDirectory); });
    registry.add("freeBody",
                 {"2D rigid body moved by the fluid force and gravity (wall-force models only)",
                  "",
                  {{"mass", "", "M"},
                   {"momentOfInertia", "", "I about the centre of mass"},
                   {"centreOfMass", "", "initial X"},
                   {"velocity", "(0 0)", "initial V"},
                   {"angularVelocity", "0", "initial omega"}}},
                 [](const Dictionary& dict, const std::string&) -> Made {
                     if constexpr (D == 2) return std::make_unique<FreeBody2D>(dict);
                     dict.fail("type", "freeBody is implemented for 2D cases only");
                 });
    return registry;
}

template PatchMotionRegistry<1> makePatchMotionRegistry<1>();
template PatchMotionRegistry<2> makePatchMotionRegistry<2>();
template PatchMotionRegistry<3> makePatchMotionRegistry<3>();

}  // namespace sph
