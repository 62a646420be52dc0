// A particle state in pieces, one per rank: each rank writes its owned particles to
// <directory>/<name>_<rank>.vtu (writeParticleFile, every field and the header), and rank 0
// writes <directory>/<name>.pvtu, which names them all, once they are all there: ParaView opens
// the .pvtu as one data set. Read back on any number of ranks M, rank r reads the pieces p with
// p mod M = r, so that no rank reads the whole state; the particles are then where the pieces
// left them, and a partition and migration put them where the boxes say.
#pragma once

#include "core/ParticleSet.hpp"
#include "io/ParticleFile.hpp"
#include "parallel/Communicator.hpp"

#include <filesystem>
#include <string>

namespace sph::parallel {

// Collective. A failure on any rank (a full disk) stops every rank with its message.
template <int D>
void writeParticlePieces(const Communicator& ranks, const std::filesystem::path& directory, const std::string& name, const ParticleSet<D>& particles,
                         const StateHeader& header, WrittenPlaces places = std::nullopt);

// Collective. `index` is the .pvtu; FatalError on every rank for a missing or unreadable piece,
// or pieces that disagree on the time, the step or the fields. Each particle carries its place
// in the serial order (orderCell, orderRank): as written by a decomposed run, or else the
// pieces' order, as a serial run reads them.
template <int D>
ParticleSet<D> readParticlePieces(const Communicator& ranks, const std::filesystem::path& index, const std::string& setName, StateHeader& header);

}  // namespace sph::parallel
