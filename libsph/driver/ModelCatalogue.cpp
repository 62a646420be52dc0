#include "driver/ModelCatalogue.hpp"

#include "analytic/AnalyticSolution.hpp"
#include "boundaryModels/BoundaryModel.hpp"
#include "densityDiffusion/DensityDiffusion.hpp"
#include "equationsOfState/EquationOfState.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "kernels/Kernel.hpp"
#include "motion/PatchMotion.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"
#include "viscosity/Viscosity.hpp"

#include <fmt/format.h>

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
            text += fmt::format("    {:<20}   {:<22} {:<10} {}\n", "", c.keyword, c.defaultValue.empty() ? "required" : "= " + c.defaultValue, c.meaning);
    }
    return text + "\n";
}

}  // namespace

std::string modelCatalogue() {
    // Names and coefficients are the same in every dimension; list the 2D registries.
    std::string text;
    text += listFamily(makeKernelRegistry<2>(), "system/sphSchemes, kernel { type ...; }");
    text += "density formulation (system/sphSchemes, density { type ...; })\n"
            "    continuity           d rho/dt = sum_j m_j v_ij . grad W_ij, integrated in time\n"
            "    summation            rho_i = sum_j m_j W_ij over fluid and wall particles\n\n";
    text += listFamily(makeViscosityRegistry(), "system/sphSchemes, viscosity { type ...; }");
    text += listFamily(makeDensityDiffusionRegistry<2>(), "system/sphSchemes, densityDiffusion { type ...; }");
    text += listFamily(makeEquationOfStateRegistry(), "constant/fluidProperties, equationOfState { type ...; c0 ...; }");
    text += listFamily(makeBoundaryModelRegistry<2>(), "constant/boundaryProperties, <patch> { type ...; }");
    text += listFamily(makePatchMotionRegistry<2>(), "constant/boundaryProperties, <patch> { motion { type ...; } }");
    text += listFamily(makeTimeIntegratorRegistry<2>(), "system/timeIntegration, integrator { type ...; }");
    text += listFamily(makeFunctionObjectRegistry<2>(), "system/controlDict, functions { <name> { type ...; } }");
    text += listFamily(makeAnalyticSolutionRegistry<2>(), "errorNorm's solution { type ...; }, a fluid region's velocity { type ...; }");
    return text;
}

}  // namespace sph
