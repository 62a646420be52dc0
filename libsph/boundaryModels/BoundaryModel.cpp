#include "boundaryModels/BoundaryModel.hpp"

#include "boundaryModels/DeficiencyCorrection.hpp"
#include "boundaryModels/DeficiencyWeightingBoundaryIntegral.hpp"
#include "boundaryModels/DeficiencyWeightingJones2010.hpp"
#include "boundaryModels/DummyParticlesAdami2012.hpp"
#include "boundaryModels/ModifiedDynamicBoundaryEnglish2022.hpp"
#include "boundaryModels/RepulsiveWall.hpp"
#include "boundaryModels/DynamicBoundaryCrespo2007.hpp"

namespace sph {

template <int D>
BoundaryModelRegistry<D> makeBoundaryModelRegistry() {
    BoundaryModelRegistry<D> registry("boundary model");
    registry.add("dummyParticles",
                 {"fixed dummy particles, pressure extrapolated from the fluid",
                  "Adami, Hu & Adams, J. Comput. Phys. 231 (2012) 7057",
                  {{"noSlip", "yes (no with artificial viscosity)", "viscous wall velocity 2 v_w - v~ (yes) or v~ (no, free slip)"},
                   {"clampNegativePressure", "yes", "wall pressure never below the background pressure"}}},
                 [](const Dictionary& dict, const ModelContext& context) -> std::unique_ptr<BoundaryModel<D>> {
                     return std::make_unique<DummyParticlesAdami2012<D>>(dict, context);
                 });
    registry.add(
        "dynamicBoundary", {"wall particles with continuity density and EOS pressure", "Crespo, Gomez-Gesteira & Dalrymple, CMC 5 (2007) 173", {}},
        [](const Dictionary&, const ModelContext&) -> std::unique_ptr<BoundaryModel<D>> { return std::make_unique<DynamicBoundaryCrespo2007<D>>(); });
    registry.add("modifiedDynamicBoundary",
                 {"mDBC: wall particles whose density is extrapolated from the fluid at their ghost nodes (first-order consistent)",
                  "English et al., Comput. Part. Mech. 9 (2022) 1",
                  {{"firstLayerOffset", "0.5", "the wall surface in front of the first layer, in spacings (as the generator's firstLayerOffset)"}}},
                 [](const Dictionary& dict, const ModelContext&) -> std::unique_ptr<BoundaryModel<D>> {
                     return std::make_unique<ModifiedDynamicBoundaryEnglish2022<D>>(dict);
                 });
    const CoefficientDoc K{"K", "", "squared velocity, ~ g H (kernel normalised to 1 at contact)"};
    const CoefficientDoc form{"form", "square", "square: r/|r|^2; shifted: r/(|r| max(|r| - shift, 0.1 dx))"};
    const CoefficientDoc shift{"shift", "dx/2", "with form shifted: distance of the singularity"};
    registry.add(
        "monaghanKajtar",
        {"repulsive force (K/beta) r/|r|^2 W/W(0) 2m_k/(m_a + m_k)", "Monaghan & Kajtar, Comput. Phys. Commun. 180 (2009) 1811", {K, form, shift}},
        [](const Dictionary& dict, const ModelContext& context) -> std::unique_ptr<BoundaryModel<D>> {
            return std::make_unique<RepulsiveWall<D>>(readRepulsionLaw(dict, context));
        });
    registry.add("lennardJones",
                 {"Dc [(r0/r)^p1 - (r0/r)^p2] r/r^2 for r < r0",
                  "Monaghan, J. Comput. Phys. 110 (1994) 399",
                  {{"Dc", "", "squared velocity, ~ 5 g H"}, {"r0", "dx", "range"}, {"p1", "12", ""}, {"p2", "4", ""}}},
                 [](const Dictionary& dict, const ModelContext& context) -> std::unique_ptr<BoundaryModel<D>> {
                     return std::make_unique<RepulsiveWall<D>>(readRepulsionLaw(dict, context));
                 });
    const std::vector<CoefficientDoc> correction{
        {"repulsion", "{ type wallDistance; K c0^2/200; damping 1; distance dx/2; springDistance distance/2; closingSpeed mean; }",
         "the partner that stops penetration: wallDistance (a damper on the closing speed within distance of the wall, on the wall "
         "particles' mean, which does not drag fluid sliding past a curved wall, or, closingSpeed each, on each one's; and a spring K "
         "within springDistance that pushes only while the fluid closes on the wall or rests: it holds a slow creep through a one-layer "
         "floor and returns nothing to an impact), monaghanKajtar or lennardJones"},
        {"calibration", "wallPressure",
         "wallPressure (virtual particles at the extrapolated wall pressure), calibrated (the paper: cancel the sample's normal "
         "acceleration, divided by the blended kernel c_s . n_j) or literal (by W_sj)"},
        {"direction", "normal", "normal (n_j) or radial (r_ij/|r_ij|)"},
        {"sample", "{ type nearest; size 4; }", "calibrated and literal: or { type withinRadius; radius r; }"},
        {"temporalSmoothing", "1", "calibrated and literal: lambda of C_j <- (1 - lambda) C_j + lambda C_j^new, in (0, 1]"}};
    registry.add("deficiencyCorrection",
                 {"boundary deficiency correction, published weighting, one layer on the wall",
                  "Jones, Yang & McCue-Weil, Ship Sci. & Tech. 4(7) (2010) 21", correction},
                 [](const Dictionary& dict, const ModelContext& context) -> std::unique_ptr<BoundaryModel<D>> {
                     return std::make_unique<DeficiencyCorrection<D, DeficiencyWeightingJones2010>>(dict, context, "deficiencyCorrection");
                 });
    registry.add("deficiencyCorrectionBoundaryIntegral",
                 {"deficiency correction weighted by wall area vectors (divergence theorem), unnormalised; the one for 3D",
                  "sphkit; METHOD.md open improvements", correction},
                 [](const Dictionary& dict, const ModelContext& context) -> std::unique_ptr<BoundaryModel<D>> {
                     return std::make_unique<DeficiencyCorrection<D, DeficiencyWeightingBoundaryIntegral>>(dict, context,
                                                                                                           "deficiencyCorrectionBoundaryIntegral");
                 });
    return registry;
}

template BoundaryModelRegistry<1> makeBoundaryModelRegistry<1>();
template BoundaryModelRegistry<2> makeBoundaryModelRegistry<2>();
template BoundaryModelRegistry<3> makeBoundaryModelRegistry<3>();

}  // namespace sph
