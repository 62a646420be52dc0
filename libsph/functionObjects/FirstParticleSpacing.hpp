// The spacing (m/rho)^(1/D) of the fluid particle that the serial run stores first: the scale
// that gauges (columnHeight, waveGauge) measure with. Collective: in a decomposed run it is the
// first particle in the serial order (orderCell, orderRank), wherever it is owned. None
// without fluid.
#pragma once

#include "functionObjects/Reductions.hpp"
#include "physics/FluidSystemView.hpp"

#include <optional>

namespace sph {

template <int D>
std::optional<double> firstParticleSpacing(const FluidSystemView<D>& system, const Reductions& reductions);

}  // namespace sph
