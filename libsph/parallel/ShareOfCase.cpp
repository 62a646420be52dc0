#include "parallel/ShareOfCase.hpp"

#include "io/ParticleState.hpp"
#include "parallel/ParticlePieces.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
#include <optional>
#include <tuple>

namespace sph::parallel {

namespace {

template <int D>
ParticleSet<D> readShare(const Communicator& ranks, const std::filesystem::path& file, const std::string& setName, StateHeader& header) {
    if (file.extension() == ".pvtu") return readParticlePieces<D>(ranks, file, setName, header);
    ParticleSet<D> set(setName);
    together(ranks, [&] { set = readParticleFile<D>(file, setName, header); });
    const auto count = static_cast<std::size_t>(ranks.size()), rank = static_cast<std::size_t>(ranks.rank());
    const std::size_t first = set.size() * rank / count, last = set.size() * (rank + 1) / count;
    std::vector<std::uint32_t> block(last - first);
    std::iota(block.begin(), block.end(), static_cast<std::uint32_t>(first));
    set.keep(block);
    if (!set.has(fields::orderCell)) {
        set.add(fields::orderCell, 0);
        auto& place = set.add(fields::orderRank, 0);
        std::iota(place.begin(), place.end(), static_cast<int>(first));
    }
    return set;
}

// A value's bytes, which equal values share (-0 taken as +0).
template <class Value>
void appendBytes(std::vector<std::byte>& bytes, Value value) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(Value));
    std::memcpy(bytes.data() + at, &value, sizeof(Value));
}

template <class Value>
Value readBytes(const std::byte* bytes) {
    Value value;
    std::memcpy(&value, bytes, sizeof(Value));
    return value;
}

}  // namespace

template <int D>
void requireDistinctOverRanks(const Communicator& ranks, const ParticleSet<D>& share, const std::filesystem::path& file, bool checkPositions) {
    const auto count = static_cast<std::size_t>(ranks.size());
    const auto reject = [&](const std::string& what) {
        return fmt::format("error: particle file '{}': {} (a corrupt or hand-edited state file?)", file.string(), what);
    };
    std::optional<std::string> error;

    std::vector<std::vector<std::byte>> idsTo(count);
    for (const std::int64_t id : share.globalId) appendBytes(idsTo[static_cast<std::size_t>(id) % count], id);
    std::vector<std::size_t> fromRank;
    const std::vector<std::byte> idBytes = ranks.exchangeWithAll(idsTo, fromRank);
    std::vector<std::int64_t> ids(idBytes.size() / sizeof(std::int64_t));
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = readBytes<std::int64_t>(idBytes.data() + k * sizeof(std::int64_t));
    std::sort(ids.begin(), ids.end());
    if (const auto twice = std::adjacent_find(ids.begin(), ids.end()); twice != ids.end())
        error = reject(fmt::format("two particles have the same id {}", *twice));

    if (checkPositions) {
        struct Record {
            std::array<double, D> position;
            std::int64_t id;
        };
        std::vector<std::vector<std::byte>> recordsTo(count);
        for (std::size_t i = 0; i < share.size(); ++i) {
            Record record{{}, share.globalId[i]};
            std::size_t hash = 0;
            for (int d = 0; d < D; ++d) {
                record.position[static_cast<std::size_t>(d)] = share.position[i][d] + 0.0;
                hash = hash * 1000003u ^ std::hash<double>{}(record.position[static_cast<std::size_t>(d)]);
            }
            appendBytes(recordsTo[hash % count], record);
        }
        const std::vector<std::byte> recordBytes = ranks.exchangeWithAll(recordsTo, fromRank);
        std::vector<Record> records(recordBytes.size() / sizeof(Record));
        for (std::size_t k = 0; k < records.size(); ++k) records[k] = readBytes<Record>(recordBytes.data() + k * sizeof(Record));
        std::sort(records.begin(), records.end(),
                  [](const Record& a, const Record& b) { return std::tie(a.position, a.id) < std::tie(b.position, b.id); });
        const auto samePlace = [](const Record& a, const Record& b) { return a.position == b.position; };
        if (const auto pair = std::adjacent_find(records.begin(), records.end(), samePlace); pair != records.end() && !error)
            error = reject(
                fmt::format("particle ids {} and {} are at the same position ({:g})", pair->id, std::next(pair)->id, fmt::join(pair->position, " ")));
    }
    ranks.stopIfAnyFailed(error);
}

template <int D>
CaseSetup<D> setUpShareOfCase(const Communicator& ranks, const std::filesystem::path& caseDirectory, const TimeDirectory& start) {
    StateShare<D> share;
    share.read = [&](const std::filesystem::path& file, const std::string& setName, StateHeader& header) {
        return readShare<D>(ranks, file, setName, header);
    };
    share.checkOnEveryRank = [&](const std::function<void()>& checks) { together(ranks, checks); };
    share.largestOverRanks = [&](std::span<double> values) { ranks.maxOverRanks(values); };
    share.requireDistinct = [&](const ParticleSet<D>& set, const std::filesystem::path& file, bool checkPositions) {
        requireDistinctOverRanks(ranks, set, file, checkPositions);
    };
    CaseSetup<D> setup;
    together(ranks, [&] { setup = setUpCase<D>(caseDirectory, start, &share); });
    return setup;
}

#define SPHKIT_INSTANTIATE(D)                                                                                           \
    template CaseSetup<D> setUpShareOfCase<D>(const Communicator&, const std::filesystem::path&, const TimeDirectory&); \
    template void requireDistinctOverRanks<D>(const Communicator&, const ParticleSet<D>&, const std::filesystem::path&, bool);
#ifdef SPHKIT_HAS_2D
SPHKIT_INSTANTIATE(2)
#endif
#ifdef SPHKIT_HAS_3D
SPHKIT_INSTANTIATE(3)
#endif
#undef SPHKIT_INSTANTIATE

}  // namespace sph::parallel
