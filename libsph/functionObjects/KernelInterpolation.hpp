// Fluid fields at a point by the Shepard-normalised kernel sum
//   f(x) = sum_j f_j W(x - x_j) V_j / sum_j W(x - x_j) V_j,  V_j = m_j/rho_j,
// over the fluid particles within the support. A point with no fluid in reach (a dry probe)
// reads zero pressure, density and velocity, and weight 0. Sample points must lie in the domain.
#pragma once

#include "core/Vector.hpp"
#include "functionObjects/Reductions.hpp"
#include "io/Dictionary.hpp"
#include "physics/FluidSystemView.hpp"

#include <string>
#include <vector>

namespace sph {

template <int D>
struct InterpolatedFluid {
    double pressure = 0.0, density = 0.0;
    Vec<D> velocity = Vec<D>::Zero();
    double weight = 0.0;  // the kernel sum, ~1 inside the fluid, ~0.5 on its surface
};

template <int D>
InterpolatedFluid<D> interpolateFluid(const FluidSystemView<D>& system, const Vec<D>& x);
// Collective: the interpolations at every point, each from the process that answers for it
// (FluidSystemView::answersFor), on every process.
template <int D>
std::vector<InterpolatedFluid<D>> interpolateFluidAt(const FluidSystemView<D>& system, const std::vector<Vec<D>>& points,
                                                     const Reductions& reductions);

// One field of an interpolated sample by name: p, rho, U (magnitude), Ux, Uy, Uz.
template <int D>
double fieldValue(const InterpolatedFluid<D>& sample, const std::string& field);
// An error naming `keyword` when `field` is not one of the names fieldValue takes in D dimensions.
template <int D>
void checkInterpolatedField(const Dictionary& dict, const std::string& keyword, const std::string& field);

// Reads the sample points of `keyword`; a point outside the domain is an error naming it (`what`: "probe", "gauge").
template <int D>
std::vector<Vec<D>> readSamplePoints(const Dictionary& dict, const std::string& keyword, const FluidSystemView<D>& system, const std::string& what);

}  // namespace sph
