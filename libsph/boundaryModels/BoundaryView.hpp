// What a boundary model reads and writes: the fluid and wall particles, the cell lists, the
// kernel and equation of state, and the body force at the evaluation's time. A model sees no
// more of the system than this: it cannot move walls, reorder particles or evaluate rates, and
// it reads fields by their keys (core/ParticleFields.hpp).
#pragma once

#include "core/ParticleSet.hpp"
#include "equationsOfState/EquationOfState.hpp"
#include "kernels/Kernel.hpp"
#include "neighbourSearch/CellLinkedList.hpp"

namespace sph {

template <int D>
struct BoundaryView {
    ParticleSet<D>& fluid;
    ParticleSet<D>& walls;
    const CellLinkedList<D>& fluidCells;
    const CellLinkedList<D>& wallCells;  // the wall particles that enter the kernel sums
    const Kernel<D>& kernel;
    const EquationOfState& eos;
    double supportRadius;
    bool continuity;  // the fluid's density evolves with densityRate
    Vec<D> gravity;   // the body force at the evaluation's time (ramped where the case ramps it)
};

}  // namespace sph
