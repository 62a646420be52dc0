#include "boundaryModels/BoundaryModel.hpp"

#include "boundaryModels/DummyParticlesAdami2012.hpp"
#include "boundaryModels/DynamicBoundaryCrespo2007.hpp"

namespace sph {

template <int D>
BoundaryModelRegistry<D> makeBoundaryModelRegistry() {
    BoundaryModelRegistry<D> registry("boundary model");
    registry.add("dummyParticles",
                 {"fixed dummy particles, pressure extrapolated from the fluid", "Adami, Hu & Adams, J. Comput. Phys. 231 (2012) 7057",
                  {{"noSlip", "yes", "viscous wall velocity 2 v_w - v~ (yes) or v~ (no, free slip)"},
                   {"clampNegativePressure", "yes", "wall pressure never below the background pressure"}}},
                 [](const Dictionary& dict) -> std::unique_ptr<BoundaryModel<D>> { return std::make_unique<DummyParticlesAdami2012<D>>(dict); });
    registry.add("dynamicBoundary", {"wall particles with continuity density and EOS pressure", "Crespo, Gomez-Gesteira & Dalrymple, CMC 5 (2007) 173", {}},
                 [](const Dictionary&) -> std::unique_ptr<BoundaryModel<D>> { return std::make_unique<DynamicBoundaryCrespo2007<D>>(); });
    return registry;
}

template BoundaryModelRegistry<1> makeBoundaryModelRegistry<1>();
template BoundaryModelRegistry<2> makeBoundaryModelRegistry<2>();
template BoundaryModelRegistry<3> makeBoundaryModelRegistry<3>();

}  // namespace sph
