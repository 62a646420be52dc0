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

#include <functional>
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
    // A decomposed run's share (libsph/parallel) holds copies of its neighbours' particles too:
    // per particle held, 1 where this process owns it, and which sample points it answers for
    // (exactly one process answers for a point, and holds every particle within a support of
    // it). Empty in the serial run: every particle and point is its own.
    std::span<const char> fluidOwned = {}, wallsOwned = {};
    std::function<bool(const Vec<D>&)> answersForPoint = {};

    bool ownsFluid(std::size_t i) const { return fluidOwned.empty() || fluidOwned[i] != 0; }
    bool ownsWall(std::size_t j) const { return wallsOwned.empty() || wallsOwned[j] != 0; }
    bool answersFor(const Vec<D>& x) const { return !answersForPoint || answersForPoint(x); }
};

}  // namespace sph
