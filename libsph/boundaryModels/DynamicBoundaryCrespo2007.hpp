// Dynamic boundary particles of Crespo, Gomez-Gesteira & Dalrymple (2007): wall particles
// obey the continuity equation with the fluid around them and take their pressure from the
// equation of state, so a wall compressed by approaching fluid pushes it back:
//   d rho_w / dt = sum_f m_f (v_w - v_f) . grad_w W_wf,     p_w = p(max(rho_w, rho0))
// The density is floored at rho0 for the pressure, as DualSPHysics does, so walls never pull.
// Several layers of wall particles (the generator's `layers`) give the fluid full support.
// Reference: A.J.C. Crespo, M. Gomez-Gesteira, R.A. Dalrymple, CMC 5 (2007) 173-184.
// Example (constant/boundaryProperties):
//   tank { type dynamicBoundary; }
#pragma once

#include "boundaryModels/BoundaryModel.hpp"

namespace sph {

template <int D>
class DynamicBoundaryCrespo2007 : public BoundaryModel<D> {
public:
    bool actsThroughWallParticles() const override { return true; }
    std::string describe() const override { return "dynamicBoundary"; }
    bool evolvesWallDensity() const override { return true; }
    // Fewer layers run (the wall pushes back through its density), but only a full support
    // gives the fluid near the wall its full kernel sum.
    int layersToGenerate(double support, double dx) const override { return layersFillingSupport(support, dx); }
    void updateWalls(const BoundaryView<D>& view, std::size_t begin, std::size_t end) override;
};

}  // namespace sph
