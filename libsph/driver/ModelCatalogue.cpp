#include "driver/ModelCatalogue.hpp"

#include "analytic/AnalyticSolution.hpp"
#include "boundaryModels/BoundaryModel.hpp"
#include "densityDiffusion/DensityDiffusion.hpp"
#include "particleShifting/ParticleShifting.hpp"
#include "equationsOfState/EquationOfState.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "kernels/Kernel.hpp"
#include "generation/WallPatches.hpp"
#include "motion/PatchMotion.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"
#include "viscosity/Viscosity.hpp"

#include <fmt/format.h>

#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sph {

namespace {

template <class Registry>
std::string listFamily(const Registry& registry, const std::string& where) {
    std::string text = fmt::format("{} ({})\n", registry.family(), where);
    for (const std::string& name : registry.names()) {
        const ModelDoc& doc = registry.doc(name);
        text += fmt::format("    {:<20} {}\n", name, doc.summary);
        if (!doc.reference.empty()) text += fmt::format("    {:<20} reference: {}\n", "", doc.reference);
        for (const CoefficientDoc& c : doc.coefficients)
            text +=
                fmt::format("    {:<20}   {:<22} {:<10} {}\n", "", c.keyword, c.defaultValue.empty() ? "required" : "= " + c.defaultValue, c.meaning);
    }
    return text + "\n";
}

}  // namespace

std::string modelCatalogue(const std::string& family) {
    // Names and coefficients are the same in every dimension; list the 2D registries.
    const std::vector<std::pair<std::string, std::function<std::string()>>> families{
        {"kernel", [] { return listFamily(makeKernelRegistry<2>(), "system/sphSchemes, kernel { type ...; }"); }},
        {"density",
         [] {
             return std::string(
                 "density formulation (system/sphSchemes, density { type ...; })\n"
                 "    continuity           d rho/dt = sum_j m_j v_ij . grad W_ij, integrated in time\n"
                 "    summation            rho_i = sum_j m_j W_ij over fluid and wall particles\n\n");
         }},
        {"viscosity", [] { return listFamily(makeViscosityRegistry(), "system/sphSchemes, viscosity { type ...; }"); }},
        {"densityDiffusion", [] { return listFamily(makeDensityDiffusionRegistry<2>(), "system/sphSchemes, densityDiffusion { type ...; }"); }},
        {"particleShifting",
         [] { return listFamily(makeParticleShiftingRegistry(), "system/sphSchemes, particleShifting { type ...; } (optional)"); }},
        {"equationOfState",
         [] { return listFamily(makeEquationOfStateRegistry(), "constant/fluidProperties, equationOfState { type ...; c0 ...; }"); }},
        {"boundary", [] { return listFamily(makeBoundaryModelRegistry<2>(), "constant/boundaryProperties, <patch> { type ...; }"); }},
        {"motion", [] { return listFamily(makePatchMotionRegistry<2>(), "constant/boundaryProperties, <patch> { motion { type ...; } }"); }},
        {"integrator", [] { return listFamily(makeTimeIntegratorRegistry<2>(), "system/timeIntegration, integrator { type ...; }"); }},
        {"functionObject", [] { return listFamily(makeFunctionObjectRegistry<2>(), "system/controlDict, functions { <name> { type ...; } }"); }},
        {"analytic",
         [] { return listFamily(makeAnalyticSolutionRegistry<2>(), "errorNorm's solution { type ...; }, a fluid region's velocity { type ...; }"); }},
        {"fluidRegion", [] { return listFamily(makeFluidShapeRegistry<2>(), "system/generateParticlesDict, fluid { <name> { type ...; } }"); }},
        {"wallPatch", [] { return listFamily(makeWallPatchRegistry<2>(), "system/generateParticlesDict, boundaries { <patch> { type ...; } }"); }},
    };
    std::string text, valid;
    for (const auto& [name, list] : families) {
        if (family.empty() || family == name) text += list();
        valid += " " + name;
    }
    if (text.empty()) throw std::invalid_argument("unknown model family '" + family + "'; valid:" + valid);
    return text;
}

}  // namespace sph
