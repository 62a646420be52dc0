// A boundary model acts on the wall particles of one patch. Models that act through wall
// particles (dummy particles, dynamic boundary) set the wall pressure, density and the
// velocity the viscous term sees, once per evaluation, before the force loop; the force loop
// then treats every wall particle alike, so it never branches on a patch's model.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"

#include <memory>
#include <string>

namespace sph {

template <int D>
class FluidSystem;

template <int D>
class BoundaryModel {
public:
    virtual ~BoundaryModel() = default;

    // One line for the run log: the type and its coefficients.
    virtual std::string describe() const = 0;

    // True when the patch's wall density is part of the integrated state.
    virtual bool evolvesWallDensity() const { return false; }

    // Sets the state of wall particles [begin, end) from the fluid at time t.
    virtual void updateWalls(FluidSystem<D>& system, std::size_t begin, std::size_t end, double t) = 0;
};

template <int D>
using BoundaryModelRegistry = Registry<std::unique_ptr<BoundaryModel<D>>, const Dictionary&>;

template <int D>
BoundaryModelRegistry<D> makeBoundaryModelRegistry();

}  // namespace sph
