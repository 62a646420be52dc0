// What the symmetric pair loop reads and writes, in the fluid cell list's order: copies of the
// per-particle inputs (so a pair reads neighbouring memory whatever the storage order) and one
// accumulator per thread (a pair adds to both its particles, which another thread may own).
// An array is sized only when the instantiated loop reads it: a term the case did not select
// allocates nothing here.
#pragma once

#include "core/Vector.hpp"

#include <cstdint>
#include <vector>

namespace sph {

template <int D>
struct CellOrderedFluid {
    std::vector<double> mass;
    std::vector<double> pressureOverDensity2;       // pressure gradient
    std::vector<Vec<D>> velocity;                   // continuity, viscosity
    std::vector<double> density;                    // viscosity, density diffusion
    std::vector<double> volume;                     // density diffusion
    std::vector<Vec<D>> densityGradient;            // delta-SPH's renormalised gradient
    std::vector<std::vector<Vec<D>>> acceleration;  // per thread
    std::vector<std::vector<double>> densityRate;   // per thread, continuity only
    std::vector<std::vector<double>> gradientSums;  // per thread, delta-SPH's gradient only
    // Per thread, delta-SPH only: each of its particles' count of later neighbours, then their
    // places, listed by the gradient pass for the pair loop.
    std::vector<std::vector<std::uint32_t>> neighbourLists;
    std::vector<std::uint8_t> cellWanted;  // per cell, where only some rates are wanted

    std::size_t bytes() const {
        std::size_t total = (mass.capacity() + pressureOverDensity2.capacity() + density.capacity() + volume.capacity()) * sizeof(double) +
                            (velocity.capacity() + densityGradient.capacity()) * sizeof(Vec<D>) + cellWanted.capacity();
        for (const auto& a : acceleration) total += a.capacity() * sizeof(Vec<D>);
        for (const auto& r : densityRate) total += r.capacity() * sizeof(double);
        for (const auto& g : gradientSums) total += g.capacity() * sizeof(double);
        for (const auto& l : neighbourLists) total += l.capacity() * sizeof(std::uint32_t);
        return total;
    }
};

}  // namespace sph
