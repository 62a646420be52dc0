#include "io/ParticleState.hpp"

#include "core/FatalError.hpp"
#include "core/FieldBytes.hpp"
#include "io/PvtuFile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace sph {

std::filesystem::path stateFile(const std::filesystem::path& directory, const std::string& name) {
    const std::filesystem::path pieces = directory / (name + ".pvtu");
    return std::filesystem::exists(pieces) ? pieces : directory / (name + ".vtu");
}

StateHeader readStateHeader(const std::filesystem::path& file) {
    return readParticleFileHeader(file.extension() == ".pvtu" ? readPvtuPieces(file).front() : file);
}

template <int D>
void appendParticles(ParticleSet<D>& set, ParticleSet<D>& piece, const std::filesystem::path& file) {
    if (writtenPointArrays(set) != writtenPointArrays(piece))
        throw FatalError("error: particle piece '" + file.string() + "' holds other fields than the pieces before it");
    const std::size_t first = set.size();
    std::vector<std::uint32_t> all(piece.size());
    std::iota(all.begin(), all.end(), 0u);
    std::vector<std::byte> message;
    pack(everyArray(piece), all, message);
    set.resize(first + piece.size());
    unpack(everyArray(set), first, message);
}

template <int D>
std::vector<std::uint32_t> serialOrder(const ParticleSet<D>& set) {
    const auto& cell = set[fields::orderCell];
    const auto& rank = set[fields::orderRank];
    // Sorted as (place, index) pairs in one array rather than as indices that look their keys up
    // (a halo build sorts every particle a rank holds).
    std::vector<std::pair<std::uint64_t, std::uint32_t>> places(set.size());
    for (std::size_t i = 0; i < set.size(); ++i) places[i] = {serialPlace(cell[i], rank[i]), static_cast<std::uint32_t>(i)};
    std::sort(places.begin(), places.end());
    std::vector<std::uint32_t> order(set.size());
    for (std::size_t k = 0; k < places.size(); ++k) order[k] = places[k].second;
    return order;
}

template <int D>
void writeParticlePiece(const std::filesystem::path& directory, const std::string& name, int rank, int count, const ParticleSet<D>& particles,
                        const StateHeader& header, const std::function<void(const std::function<void()>&)>& together, WrittenPlaces places) {
    together([&] { writeParticleFile(directory / fmt::format("{}_{}.vtu", name, rank), particles, header, places); });
    together([&] {
        if (rank != 0) return;
        std::vector<std::string> pieces;
        for (int r = 0; r < count; ++r) pieces.push_back(fmt::format("{}_{}.vtu", name, r));
        writePvtu(directory / (name + ".pvtu"), writtenPointArrays(particles), pieces);
    });
}

template <int D>
ParticleSet<D> readParticleState(const std::filesystem::path& file, const std::string& setName, StateHeader& header) {
    if (file.extension() != ".pvtu") return readParticleFile<D>(file, setName, header);
    const std::vector<std::filesystem::path> pieces = readPvtuPieces(file);
    ParticleSet<D> set = readParticleFile<D>(pieces.front(), setName, header);
    for (std::size_t p = 1; p < pieces.size(); ++p) {
        StateHeader pieceHeader;
        ParticleSet<D> piece = readParticleFile<D>(pieces[p], setName, pieceHeader);
        if (pieceHeader.time != header.time || pieceHeader.step != header.step)
            throw FatalError(fmt::format("error: particle piece '{}' is of t = {:g} (step {}), '{}' of t = {:g} (step {})", pieces[p].string(),
                                         pieceHeader.time, pieceHeader.step, pieces.front().string(), header.time, header.step));
        appendParticles(set, piece, pieces[p]);
    }
    if (!set.has(fields::orderCell) || !set.has(fields::orderRank)) return set;
    // The serial order; the numbers themselves are the decomposed run's, not the state's.
    set.permute(serialOrder(set));
    set.remove(fields::orderCell);
    set.remove(fields::orderRank);
    return set;
}

#define SPHKIT_INSTANTIATE(D)                                                                                                                  \
    template ParticleSet<D> readParticleState<D>(const std::filesystem::path&, const std::string&, StateHeader&);                              \
    template void appendParticles<D>(ParticleSet<D>&, ParticleSet<D>&, const std::filesystem::path&);                                          \
    template void writeParticlePiece<D>(const std::filesystem::path&, const std::string&, int, int, const ParticleSet<D>&, const StateHeader&, \
                                        const std::function<void(const std::function<void()>&)>&, WrittenPlaces);                              \
    template std::vector<std::uint32_t> serialOrder<D>(const ParticleSet<D>&);
SPHKIT_INSTANTIATE(1)
SPHKIT_INSTANTIATE(2)
SPHKIT_INSTANTIATE(3)
#undef SPHKIT_INSTANTIATE

}  // namespace sph
