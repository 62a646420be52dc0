#include "functionObjects/FunctionObject.hpp"

#include "functionObjects/BodyMotion.hpp"
#include "functionObjects/ColumnHeight.hpp"
#include "functionObjects/FieldErrorNorm.hpp"
#include "functionObjects/FieldTotals.hpp"
#include "functionObjects/LineSample.hpp"
#include "functionObjects/PatchForces.hpp"
#include "functionObjects/Probes.hpp"
#include "functionObjects/SurgeFront.hpp"
#include "functionObjects/WallPenetrations.hpp"
#include "functionObjects/WallPressureSensors.hpp"
#include "functionObjects/WaveGauge.hpp"

namespace sph {

namespace {

template <class Object, int D>
void add(FunctionObjectRegistry<D>& registry, const std::string& name, ModelDoc doc) {
    registry.add(name, std::move(doc), [](const Dictionary& dict, const FunctionObjectContext<D>& context) -> std::unique_ptr<FunctionObject<D>> {
        return std::make_unique<Object>(dict, context);
    });
}

}  // namespace

template <int D>
FunctionObjectRegistry<D> makeFunctionObjectRegistry() {
    const CoefficientDoc interval{"executeInterval", "0", "simulated time between executions (0: every step)"};
    const CoefficientDoc reference{"reference", "none",
                                   "{ file; time; columns (...); timeScale; valueScale; valueOffset; scale; }: error "
                                   "over time against a CSV"};
    FunctionObjectRegistry<D> registry("function object");
    add<SurgeFront<D>>(registry, "surgeFront",
                       {"leading fluid particle along a direction, over time",
                        "Martin & Moyce, Phil. Trans. R. Soc. A 244 (1952) 312",
                        {{"origin", "", "point the front is measured from"}, {"direction", "", "direction of the surge"}, reference, interval}});
    add<LineSample<D>>(registry, "lineSample",
                       {"kernel-interpolated p and rho along a line, optional hydrostatic error",
                        "",
                        {{"start", "", "first point"},
                         {"end", "", "last point"},
                         {"points", "", "number of samples (>= 2)"},
                         {"hydrostaticReference", "none", "{ freeSurfaceHeight H; }: error against rho0 |g| (H - z)"},
                         {"reference", "none", "{ file; coordinate; axis; field; columns (...); scale; }: error against a CSV profile"},
                         interval}});
    add<BodyMotion<D>>(registry, "bodyMotion",
                       {"position, angle, velocities and fluid loads of a free body (2D)", "", {{"patch", "", "the body's patch"}, interval}});
    add<Probes<D>>(registry, "probes",
                   {"kernel-interpolated fields at points, over time",
                    "",
                    {{"points", "", "((x y ...) ...)"}, {"fields", "", "(p rho U Ux Uy Uz)"}, reference, interval}});
    add<ColumnHeight<D>>(registry, "columnHeight",
                         {"water height above gauge points, over time",
                          "",
                          {{"points", "", "gauge points ((x y ...) ...)"}, {"radius", "h", "reach around the vertical"}, reference, interval}});
    add<WaveGauge<D>>(registry, "waveGauge",
                      {"free-surface elevation where the interpolated volume fraction crosses a threshold, over time",
                       "",
                       {{"points", "", "gauge points ((x y ...) ...); each gauge reads upwards, against gravity"},
                        {"threshold", "0.5", "volume fraction sum_j V_j W_ij read as the surface"},
                        {"length", "to the domain's boundary", "length of each gauge's line"},
                        {"patch", "none (lab frame)", "the gauges move with this patch's motion"},
                        reference,
                        interval}});
    add<WallPressureSensors<D>>(registry, "wallPressure",
                                {"pressure sensors on a wall patch (area-weighted wall-particle pressure), over time",
                                 "Adami, Hu & Adams, J. Comput. Phys. 231 (2012) 7057 (the extrapolation where the model sets none)",
                                 {{"patch", "", "the wall patch the sensors sit on"},
                                  {"points", "", "sensor centres on the wall ((x y ...) ...), where the patch was generated"},
                                  {"size", "the wall spacing", "sensor diameter (2D: length along the wall)"},
                                  {"timeWindow", "0 (none)", "trailing moving average over this simulated time, beside the raw signal"},
                                  {"source", "model", "model: the wall particles' pressure where the model sets one; fluid: the fluid extrapolated"},
                                  reference,
                                  interval}});
    add<FieldErrorNorm<D>>(registry, "errorNorm",
                           {"L1, L2, Linf of a field against an analytic solution",
                            "",
                            {{"field", "", "U or p"},
                             {"solution", "", "{ type ...; }: see analytic solutions"},
                             {"scale", "1", "errors are divided by it"},
                             {"subtractMean", "no", "compare p up to a constant"},
                             interval}});
    add<PatchForces<D>>(registry, "forces",
                        {"force of the fluid on wall-particle patches, over time", "", {{"patches", "", "(name ...)"}, interval}});
    add<FieldTotals<D>>(registry, "fieldTotals", {"total mass, kinetic energy and momentum, over time", "", {interval}});
    add<WallPenetrations<D>>(registry, "wallPenetrations", {"fluid particles behind a wall's first layer, counted every step", "", {interval}});
    return registry;
}

template FunctionObjectRegistry<1> makeFunctionObjectRegistry<1>();
template FunctionObjectRegistry<2> makeFunctionObjectRegistry<2>();
template FunctionObjectRegistry<3> makeFunctionObjectRegistry<3>();

}  // namespace sph
