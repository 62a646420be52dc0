#include "functionObjects/FunctionObject.hpp"

#include "functionObjects/BodyMotion.hpp"
#include "functionObjects/LineSample.hpp"
#include "functionObjects/SurgeFront.hpp"

namespace sph {

template <int D>
FunctionObjectRegistry<D> makeFunctionObjectRegistry() {
    const CoefficientDoc interval{"executeInterval", "0", "simulated time between executions (0: every step)"};
    FunctionObjectRegistry<D> registry("function object");
    registry.add("surgeFront", {"leading fluid particle along a direction, over time", "Martin & Moyce, Phil. Trans. R. Soc. A 244 (1952) 312",
                                {{"origin", "", "point the front is measured from"}, {"direction", "", "direction of the surge"}, interval}},
                 [](const Dictionary& dict, const FunctionObjectContext& context) -> std::unique_ptr<FunctionObject<D>> {
                     return std::make_unique<SurgeFront<D>>(dict, context);
                 });
    registry.add("lineSample", {"kernel-interpolated p and rho along a line, optional hydrostatic error", "",
                                {{"start", "", "first point"}, {"end", "", "last point"}, {"points", "", "number of samples (>= 2)"},
                                 {"hydrostaticReference", "none", "{ freeSurfaceHeight H; }: error against rho0 |g| (H - z)"}, interval}},
                 [](const Dictionary& dict, const FunctionObjectContext& context) -> std::unique_ptr<FunctionObject<D>> {
                     return std::make_unique<LineSample<D>>(dict, context);
                 });
    registry.add("bodyMotion", {"position, angle, velocities and fluid loads of a free body (2D)", "", {{"patch", "", "the body's patch"}, interval}},
                 [](const Dictionary& dict, const FunctionObjectContext& context) -> std::unique_ptr<FunctionObject<D>> {
                     return std::make_unique<BodyMotion<D>>(dict, context);
                 });
    return registry;
}

template FunctionObjectRegistry<1> makeFunctionObjectRegistry<1>();
template FunctionObjectRegistry<2> makeFunctionObjectRegistry<2>();
template FunctionObjectRegistry<3> makeFunctionObjectRegistry<3>();

}  // namespace sph
