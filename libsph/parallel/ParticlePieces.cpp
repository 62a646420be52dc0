#include "parallel/ParticlePieces.hpp"

#include "core/FatalError.hpp"
#include "io/ParticleState.hpp"
#include "io/PvtuFile.hpp"

#include <fmt/format.h>

#include <numeric>
#include <optional>

namespace sph::parallel {

template <int D>
void writeParticlePieces(const Communicator& ranks, const std::filesystem::path& directory, const std::string& name, const ParticleSet<D>& particles,
                         const StateHeader& header, WrittenPlaces places) {
    writeParticlePiece(
        directory, name, ranks.rank(), ranks.size(), particles, header, [&](const std::function<void()>& stage) { together(ranks, stage); }, places);
}

template <int D>
ParticleSet<D> readParticlePieces(const Communicator& ranks, const std::filesystem::path& index, const std::string& setName, StateHeader& header) {
    ParticleSet<D> set(setName);
    std::vector<double> pieceSizes;  // of every piece: this rank's entries filled
    together(ranks, [&] {
        const std::vector<std::filesystem::path> pieces = readPvtuPieces(index);
        pieceSizes.assign(pieces.size(), 0.0);
        // A rank without a piece of its own takes the fields and the header from the first one.
        const bool hasPiece = static_cast<std::size_t>(ranks.rank()) < pieces.size();
        set = readParticleFile<D>(pieces[hasPiece ? static_cast<std::size_t>(ranks.rank()) : 0], setName, header);
        if (!hasPiece) set.resize(0);
        if (hasPiece) pieceSizes[static_cast<std::size_t>(ranks.rank())] = static_cast<double>(set.size());
        for (std::size_t p = static_cast<std::size_t>(ranks.rank()) + static_cast<std::size_t>(ranks.size()); p < pieces.size();
             p += static_cast<std::size_t>(ranks.size())) {
            StateHeader pieceHeader;
            ParticleSet<D> piece = readParticleFile<D>(pieces[p], setName, pieceHeader);
            if (pieceHeader.time != header.time || pieceHeader.step != header.step)
                throw FatalError(fmt::format("error: particle piece '{}' is of t = {:g} (step {}), the one before it of t = {:g} (step {})",
                                             pieces[p].string(), pieceHeader.time, pieceHeader.step, header.time, header.step));
            pieceSizes[p] = static_cast<double>(piece.size());
            appendParticles(set, piece, pieces[p]);
        }
    });
    // Every rank has a header now: the same on all, or pieces of different writes were mixed.
    const auto step = static_cast<double>(header.step);
    if (ranks.maxOverRanks(header.time) != -ranks.maxOverRanks(-header.time) || ranks.maxOverRanks(step) != -ranks.maxOverRanks(-step))
        throw FatalError("error: the pieces of '" + index.string() + "' are of different times or steps");
    const double ordered = set.has(fields::orderCell) && set.has(fields::orderRank) ? 1.0 : 0.0;
    if (ranks.maxOverRanks(ordered) != -ranks.maxOverRanks(-ordered))
        throw FatalError("error: some pieces of '" + index.string() + "' hold the fields orderCell and orderRank and others do not");
    if (ordered > 0.0) return set;
    // Not written by a decomposed run: the serial order is the pieces' order (as a serial run
    // reads them), each piece's particles in turn.
    ranks.maxOverRanks(pieceSizes);
    set.add(fields::orderCell, 0);
    auto& place = set.add(fields::orderRank, 0);
    std::size_t next = 0;
    for (std::size_t p = static_cast<std::size_t>(ranks.rank()); p < pieceSizes.size(); p += static_cast<std::size_t>(ranks.size())) {
        const double before = std::accumulate(pieceSizes.begin(), pieceSizes.begin() + static_cast<std::ptrdiff_t>(p), 0.0);
        for (std::size_t k = 0; k < static_cast<std::size_t>(pieceSizes[p]); ++k) place[next++] = static_cast<int>(before) + static_cast<int>(k);
    }
    return set;
}

#define SPHKIT_INSTANTIATE(D)                                                                                                       \
    template void writeParticlePieces(const Communicator&, const std::filesystem::path&, const std::string&, const ParticleSet<D>&, \
                                      const StateHeader&, WrittenPlaces);                                                           \
    template ParticleSet<D> readParticlePieces(const Communicator&, const std::filesystem::path&, const std::string&, StateHeader&);
SPHKIT_INSTANTIATE(1)
SPHKIT_INSTANTIATE(2)
SPHKIT_INSTANTIATE(3)
#undef SPHKIT_INSTANTIATE

}  // namespace sph::parallel
