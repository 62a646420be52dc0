// Modified dynamic boundary conditions (mDBC) of English et al. (2022): wall particles in layers,
// as the dynamic boundary, whose density is not integrated but extrapolated from the fluid at
// every evaluation. Wall particle w at depth d_w = (layer + firstLayerOffset) spacing behind the
// wall surface has a ghost node mirrored across the surface into the fluid, x_g = x_w + 2 d_w n_w.
// The density at the ghost node and its gradient come from the fluid f around it by the
// first-order consistent interpolation (Liu & Liu 2006), with V_f = m_f/rho_f, r = x_g - x_f and
// grad W the gradient at x_g:
//   [ sum V_f W        -sum V_f W r^T       ] [ rho_g      ]   [ sum m_f W      ]
//   [ sum V_f grad W   -sum V_f grad W r^T  ] [ grad rho_g ] = [ sum m_f grad W ]
// which reproduces a linear density field exactly, however little of the support the fluid fills.
// The wall particle takes the linear extrapolation and the pressure of the equation of state:
//   rho_w = rho_g + (x_w - x_g) . grad rho_g,     p_w = p(max(rho_w, rho0))
// Where the matrix is near singular (|det| < 1e-3: few fluid neighbours, at a free surface) the
// Shepard value rho_w = sum m_f W / sum V_f W is taken, and with no fluid neighbour rho0. The
// viscous term sees the wall's own velocity, as with the dynamic boundary. Corner particles are
// mirrored along their (diagonal) normal, by their depth, an approximation of the paper's
// mirroring through the corner point.
// Reference: A. English, J.M. Dominguez, R. Vacondio, A.J.C. Crespo, P.K. Stansby, S.J. Lind,
// L. Chiapponi, M. Gomez-Gesteira, Comput. Part. Mech. 9 (2022) 1-15; the interpolation:
// M.B. Liu, G.R. Liu, Appl. Numer. Math. 56 (2006) 19-36.
// Example (constant/boundaryProperties):
//   tank { type modifiedDynamicBoundary; firstLayerOffset 0.5; }
#pragma once

#include "boundaryModels/BoundaryModel.hpp"

namespace sph {

template <int D>
class ModifiedDynamicBoundaryEnglish2022 : public BoundaryModel<D> {
public:
    explicit ModifiedDynamicBoundaryEnglish2022(const Dictionary& dict);

    bool actsThroughWallParticles() const override { return true; }
    std::string describe() const override;
    // The ghost nodes see the fluid, but the fluid near the wall needs the support filled.
    int minimumLayers(double support, double dx) const override { return layersFillingSupport(support, dx); }
    // Fluid i reads wall w within the support, whose density reads the fluid within the support
    // of its ghost node, twice w's depth in front of it.
    double reach(double support) const override { return 2.0 * deepest_ + support; }
    void addFields(const BoundaryView<D>& view) override;
    void updateWalls(const BoundaryView<D>& view, std::size_t begin, std::size_t end) override;

private:
    double firstLayerOffset_;  // the wall surface's distance in front of the first layer, in spacings
    double deepest_ = 0.0;     // the largest depth of a wall particle, any patch's (a bound on this one's)
};

}  // namespace sph
