// A particle state as the solver reads it: <name>.vtu, or <name>.pvtu with its pieces (a
// decomposed run's output, doc/fileFormats.md) read one after the other into one set. Pieces carry
// each particle's place in the serial storage order as two fields, orderCell and orderRank (its
// cell at the last sort by cell, its place among that cell's particles); the particles are put
// back in that order, so that a run continues from pieces, on any number of ranks or on one, as
// it would have from the serial state.
#pragma once

#include "core/ParticleFields.hpp"
#include "core/ParticleSet.hpp"
#include "io/ParticleFile.hpp"

#include <filesystem>
#include <functional>
#include <string>

namespace sph {

namespace fields {
inline constexpr IntegerField orderCell{"orderCell"};
inline constexpr IntegerField orderRank{"orderRank"};
}  // namespace fields

// A particle's place in the serial order as one integer: its orderCell (cells are numbered below
// 2^32: as unsigned, whatever the int holding it reads), then its orderRank (from 0).
inline std::uint64_t serialPlace(int orderCell, int orderRank) {
    return (std::uint64_t{static_cast<std::uint32_t>(orderCell)} << 32) | static_cast<std::uint32_t>(orderRank);
}

// The places of a set's particles in the serial order (sorted by orderCell, then orderRank).
template <int D>
std::vector<std::uint32_t> serialOrder(const ParticleSet<D>& set);

// <directory>/<name>.pvtu if it exists, else <directory>/<name>.vtu (which a read then finds or names
// as missing).
std::filesystem::path stateFile(const std::filesystem::path& directory, const std::string& name);

// The header of a .vtu, or of a .pvtu's first piece.
StateHeader readStateHeader(const std::filesystem::path& file);

// Writer `rank` of `count` writes its particles (those at `places`, as writeParticleFile) as
// <directory>/<name>_<rank>.vtu, then writer 0 the index <directory>/<name>.pvtu naming every
// piece. `together` runs each of the two stages on every writer and stops all where one fails,
// so that the index follows the last piece.
template <int D>
void writeParticlePiece(const std::filesystem::path& directory, const std::string& name, int rank, int count, const ParticleSet<D>& particles,
                        const StateHeader& header, const std::function<void(const std::function<void()>&)>& together,
                        WrittenPlaces places = std::nullopt);

// A .vtu or a .pvtu (FatalError naming the file for a missing or inconsistent piece).
template <int D>
ParticleSet<D> readParticleState(const std::filesystem::path& file, const std::string& setName, StateHeader& header);

// Appends the particles of `piece` to `set`: the same written fields, or FatalError naming `file`.
template <int D>
void appendParticles(ParticleSet<D>& set, ParticleSet<D>& piece, const std::filesystem::path& file);

}  // namespace sph
