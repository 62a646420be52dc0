// What the native integrators advance, and the one update they all make of it.
// The evolved state is the fluid's position and velocity, and every density that follows the
// continuity equation: the fluid's (continuity formulation) and the walls' (dynamic boundary).
#pragma once

#include "core/ParticleSet.hpp"
#include "timeIntegrators/IntegrableSystem.hpp"

#include <vector>

namespace sph {

// out = base + c rate over the first n entries (out may alias base).
template <class T>
void addScaled(std::vector<T>& out, const std::vector<T>& base, double c, const std::vector<T>& rate, std::size_t n) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) out[i] = base[i] + c * rate[i];
}

// The particle sets whose "density" evolves with the rate "densityRate", with their owned counts.
template <int D>
std::vector<ParticleSet<D>*> evolvedDensitySets(IntegrableSystem<D>& system) {
    std::vector<ParticleSet<D>*> sets;
    if (system.continuity()) sets.push_back(&system.fluid);
    if (system.wallDensityEvolves()) sets.push_back(&system.walls);
    return sets;
}

// The evolved state at the start of a step, for the schemes that combine it with later stages.
template <int D>
struct StepStart {
    std::vector<Vec<D>> position, velocity;
    std::vector<std::vector<double>> density;  // per set of evolvedDensitySets

    void save(IntegrableSystem<D>& system, const std::vector<ParticleSet<D>*>& densitySets) {
        position = system.fluid.position;
        velocity = system.fluid[fields::velocity];
        density.resize(densitySets.size());
        for (std::size_t s = 0; s < densitySets.size(); ++s) density[s] = (*densitySets[s])[fields::density];
    }
};

}  // namespace sph
