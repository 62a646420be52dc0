// Assembles a FluidSystem and its integrator from a case directory and a start time: reads
// the dictionaries, selects every model through its registry (echoing each selection with its
// coefficients) and validates the state before the first step.
#pragma once

#include "driver/CaseDirectory.hpp"
#include "io/ParticleFile.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sph {

template <int D>
struct CaseSetup {
    std::unique_ptr<FluidSystem<D>> system;
    std::unique_ptr<TimeIntegrator<D>> integrator;
    std::string integratorType;  // its name in system/timeIntegration
    double rho0 = 0.0;
    double courant = 0.2;
    double maxDeltaT = 0.0;    // +inf when not given
    double fixedDeltaT = 0.0;  // 0: adaptive
    StateHeader header;
    std::vector<std::string> patchNames;
    std::vector<double> patchLayers;       // as the wall state records them (ParticleFile.hpp)
    std::vector<Dictionary> dictionaries;  // checked for unused keywords once everything is read
};

// How a rank of a decomposed run sets up its share of the case rather than the whole of it:
// the particles it reads, and the checks that need every rank's particles.
template <int D>
struct StateShare {
    // This rank's particles of a state file (FatalError on every rank for a bad file).
    std::function<ParticleSet<D>(const std::filesystem::path& file, const std::string& setName, StateHeader& header)> read;
    // Runs checks of this rank's particles; a FatalError on any rank stops every rank.
    std::function<void(const std::function<void()>& checks)> checkOnEveryRank;
    // Each entry its largest value over the ranks.
    std::function<void(std::span<double>)> largestOverRanks;
    // FatalError on every rank for two particles of one id in the whole state (checkPositions:
    // or two at one position).
    std::function<void(const ParticleSet<D>& share, const std::filesystem::path& file, bool checkPositions)> requireDistinct;
};

// The whole case, or with `share` this rank's share of its particles (the models and checks the same).
template <int D>
CaseSetup<D> setUpCase(const std::filesystem::path& caseDirectory, const TimeDirectory& start, const StateShare<D>* share = nullptr);

}  // namespace sph
