// What post-processing reads of the system (function objects, FluidSystem::view()): the
// particles, the patches, the cell lists and the models that kernel interpolation and wall
// loads need, read only. A function object cannot change the state, move a wall or evaluate
// rates, and it reads fields by their keys (core/ParticleFields.hpp).
#pragma once

#include "core/ParticleSet.hpp"
#include "kernels/Kernel.hpp"
#include "neighbourSearch/CellLinkedList.hpp"
#include "physics/Gravity.hpp"
#include "physics/Patch.hpp"
#include "viscosity/Viscosity.hpp"

#include <span>

namespace sph {

template <int D>
struct FluidSystemView {
    const ParticleSet<D>& fluid;
    const ParticleSet<D>& walls;
    std::span<const Patch<D>> patches;
    const CellLinkedList<D>& fluidCells;
    const CellLinkedList<D>& wallCells;  // the wall particles that enter the kernel sums
    const Kernel<D>& kernel;
    const Viscosity& viscosity;
    double supportRadius;
    double smoothingLength;
    bool viscous;  // the case selected a viscosity (walls then carry viscousVelocity)
    Vec<D> domainMin, domainMax;
    Gravity<D> gravity;
};

}  // namespace sph
