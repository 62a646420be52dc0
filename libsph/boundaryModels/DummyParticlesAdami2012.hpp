// Fixed dummy wall particles with the generalised wall condition of Adami, Hu & Adams (2012).
// Each wall particle w takes its pressure from the fluid particles f around it:
//   p_w = [ sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf ] / sum_f W_wf,   r_wf = x_w - x_f
//   rho_w = rho(p_w) by the inverse equation of state
// and, for the viscous term, the velocity  2 v_w - v~_w (noSlip) or v~_w (slip), with
// v~_w = sum_f v_f W_wf / sum_f W_wf. Negative wall pressure is clamped to the background
// pressure unless clampNegativePressure is off (tension at a wall makes fluid stick to it).
// noSlip defaults to yes with a physical viscosity and to no with artificial viscosity: there
// the mirrored velocity enters Monaghan's term, which acts on the approach speed along r and is
// no shear stress, so the wall brakes the flow (the standard 2D dam break at H/dx = 40: the
// front reaches the downstream wall Delta T = 0.29 late, the wall pressure reads 35 % below free slip;
// doc/validation.md). An explicit noSlip yes there is kept, with a warning.
// Reference: S. Adami, X.Y. Hu, N.A. Adams, J. Comput. Phys. 231 (2012) 7057-7075, Eqs. (22)-(28).
// Example (constant/boundaryProperties):
//   tank { type dummyParticles; noSlip yes; clampNegativePressure yes; }
#pragma once

#include "boundaryModels/BoundaryModel.hpp"

#include <cmath>

namespace sph {

template <int D>
class DummyParticlesAdami2012 : public BoundaryModel<D> {
public:
    DummyParticlesAdami2012(const Dictionary& dict, const ModelContext& context);

    bool actsThroughWallParticles() const override { return true; }
    // The first fluid row sits dx/2 from the wall surface, so the layers must reach support - dx/2 behind it.
    int minimumLayers(double support, double dx) const override { return layersFillingSupport(support, dx); }
    std::string describe() const override;
    void updateWalls(const BoundaryView<D>& view, std::size_t begin, std::size_t end) override;

private:
    bool noSlip_;
    bool clampNegativePressure_;
};

}  // namespace sph
