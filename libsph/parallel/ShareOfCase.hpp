// A decomposed run's start: each rank reads and sets up a share of the case's particles, so that
// no rank holds the whole state (StateShare). From pieces (a .pvtu), rank r of M reads the
// pieces p with p mod M = r (readParticlePieces); from one .vtu (a serial run's or
// generateParticles' state), every rank reads the file and keeps its block, a 1/M of it. Each
// particle carries its place in the serial order (the fields orderCell and orderRank) for
// DistributedSystem, which then moves it to the rank that owns it.
#pragma once

#include "driver/FluidSetup.hpp"
#include "parallel/Communicator.hpp"

namespace sph::parallel {

// Collective. FatalError on every rank for a bad case.
template <int D>
CaseSetup<D> setUpShareOfCase(const Communicator& ranks, const std::filesystem::path& caseDirectory, const TimeDirectory& start);

// Collective. FatalError on every rank where two particles of the ranks' shares together have
// one id, or (checkPositions) one position: each id and position goes to one rank chosen by its
// value, where equal ones meet.
template <int D>
void requireDistinctOverRanks(const Communicator& ranks, const ParticleSet<D>& share, const std::filesystem::path& file, bool checkPositions);

}  // namespace sph::parallel
