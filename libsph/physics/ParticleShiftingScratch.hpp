// What the particle-shifting pass (ParticleShiftingPass.tpp) keeps between steps: its per-particle
// arrays, sized once and reused, so that a step allocates nothing (allocating and zeroing them
// each step cost a tenth of the run in the kernel's page faults).
#pragma once

#include "core/Vector.hpp"
#include "kernels/KernelOutsideFraction.hpp"
#include "particleShifting/TensileShiftingWeight.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace sph {

template <int D>
struct ParticleShiftingScratch {
    // One particle's pass-1 sums: moment matrix, concentration gradient, the law's sum, and the
    // density differences of the renormalised density gradient.
    struct Sums {
        Eigen::Matrix<double, D, D> moment = Eigen::Matrix<double, D, D>::Zero();
        Vec<D> gradient = Vec<D>::Zero(), law = Vec<D>::Zero(), densityDifferences = Vec<D>::Zero();
    };
    std::vector<std::vector<Sums>> sumsOfThread;  // in cell order
    std::vector<double> volume, density;          // in cell order
    std::size_t summingThreads = 0;               // how many of sumsOfThread hold the last sums
    // Set by an evaluation whose force loop took the pair sums (FluidRates.tpp), at the state it
    // evaluated: the pass reuses them if the state has not changed since.
    bool summedByRates = false;
    // Where the force loop left the moment and density-difference sums in delta-SPH's per-thread
    // gradient sums (D x D + D per place, the same sums): null where they are in sumsOfThread.
    const std::vector<std::vector<double>>* momentSumsOfThread = nullptr;
    TensileShiftingWeight weight;
    double inverseWdx = 0.0;  // 1 / W(dx)
    std::vector<Vec<D>> outward, law, surfaceNormal, densityGradient;
    std::vector<char> nearWall;
    std::optional<KernelOutsideFraction<D>> outsideFraction;  // one-layer walls only
};

}  // namespace sph
