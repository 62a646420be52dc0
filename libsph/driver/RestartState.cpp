#include "driver/RestartState.hpp"

#include "timeIntegrators/EvolvedState.hpp"

namespace sph {

namespace {

constexpr const char* integratorKey = "integrator";
std::string motionKey(const std::string& patch) { return "motion:" + patch; }

}  // namespace

template <int D>
void collectRestartState(const FluidSystem<D>& system, const TimeIntegrator<D>& integrator, const std::string& integratorType, StateHeader& header) {
    header.integrator = integratorType;
    header.restart.clear();
    if (auto state = integrator.savedState(); !state.empty()) header.restart[integratorKey] = std::move(state);
    for (const Patch<D>& patch : system.patches)
        if (patch.motion)
            if (auto state = patch.motion->savedState(); !state.empty()) header.restart[motionKey(patch.name)] = std::move(state);
}

template <int D>
void restoreRestartState(FluidSystem<D>& system, TimeIntegrator<D>& integrator, const std::string& integratorType, const StateHeader& header,
                         double t, const std::string& source) {
    const bool writtenBySolver = !header.integrator.empty();
    for (Patch<D>& patch : system.patches) {
        if (const auto saved = header.restart.find(motionKey(patch.name)); patch.motion && saved != header.restart.end())
            patch.motion->restore(saved->second, source);
        if (writtenBySolver) patch.model->resume(system.boundaryView(t), patch.begin, patch.end);
    }
    const bool sameIntegrator = header.integrator == integratorType;
    const auto saved = header.restart.find(integratorKey);
    integrator.resume(system, sameIntegrator && saved != header.restart.end() ? saved->second : std::vector<double>{});

    // The rates a step starts from were evaluated before the last step's particle shift: the
    // uninterrupted run reads those, so the restart keeps them too.
    const bool keepWrittenRates = sameIntegrator && (integrator.carriesPredictedRates() || system.shiftsParticles());
    std::vector<Vec<D>> acceleration;
    std::vector<std::vector<double>> densityRates;
    const auto densitySets = evolvedDensitySets(system);
    if (keepWrittenRates) {
        acceleration = system.fluid[fields::acceleration];
        for (ParticleSet<D>* set : densitySets) densityRates.push_back((*set)[fields::densityRate]);
    }
    system.evaluateRates(t);
    if (keepWrittenRates) {
        system.fluid[fields::acceleration] = std::move(acceleration);
        for (std::size_t s = 0; s < densitySets.size(); ++s) (*densitySets[s])[fields::densityRate] = std::move(densityRates[s]);
    }
}

#define SPHKIT_INSTANTIATE(D)                                                                                                \
    template void collectRestartState<D>(const FluidSystem<D>&, const TimeIntegrator<D>&, const std::string&, StateHeader&); \
    template void restoreRestartState<D>(FluidSystem<D>&, TimeIntegrator<D>&, const std::string&, const StateHeader&, double, const std::string&);
#ifdef SPHKIT_HAS_1D
SPHKIT_INSTANTIATE(1)
#endif
#ifdef SPHKIT_HAS_2D
SPHKIT_INSTANTIATE(2)
#endif
#ifdef SPHKIT_HAS_3D
SPHKIT_INSTANTIATE(3)
#endif
#undef SPHKIT_INSTANTIATE

}  // namespace sph
