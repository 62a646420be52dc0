#include "parallel/ParticleMigration.hpp"

#include "core/FieldBytes.hpp"

#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace sph::parallel {

namespace {

// The ranks' sets must hold the same fields, or a message is read with the wrong layout.
void requireSameLayout(const Communicator& ranks, const std::string& setName, std::size_t record) {
    const auto mine = static_cast<double>(record);
    if (ranks.maxOverRanks(mine) != -ranks.maxOverRanks(-mine))
        throw std::logic_error("particle set '" + setName + "' holds different fields on different ranks");
}

}  // namespace

template <int D>
MigrationCounts migrateParticles(const Communicator& ranks, ParticleSet<D>& set, const DomainBoxes<D>& boxes) {
    set.resize(set.ownedCount());
    std::vector<std::vector<std::uint32_t>> leaving(static_cast<std::size_t>(ranks.size()));
    std::vector<std::uint32_t> staying;
    std::optional<std::string> lost;
    for (std::size_t i = 0; i < set.size(); ++i) {
        const int owner = boxes.ownerOf(set.position[i]);
        if (owner < 0) {
            if (!lost) lost = "particle " + std::to_string(set.globalId[i]) + " of '" + set.name() + "' lies in no rank's box";
        } else if (owner == ranks.rank()) {
            staying.push_back(static_cast<std::uint32_t>(i));
        } else {
            leaving[static_cast<std::size_t>(owner)].push_back(static_cast<std::uint32_t>(i));
        }
    }
    ranks.stopIfAnyFailed(lost);

    const std::vector<FieldBytes> arrays = everyArray(set);
    requireSameLayout(ranks, set.name(), bytesPerParticle(arrays));
    std::vector<std::vector<std::byte>> messages(leaving.size());
    MigrationCounts counts;
    for (std::size_t r = 0; r < leaving.size(); ++r) {
        pack(arrays, leaving[r], messages[r]);
        counts.sent += leaving[r].size();
    }
    std::vector<std::size_t> fromRank;
    const std::vector<std::byte> arrived = ranks.exchangeWithAll(messages, fromRank);

    const std::size_t record = bytesPerParticle(arrays);
    counts.received = arrived.size() / record;
    set.keep(staying);
    set.resize(staying.size() + counts.received);
    const std::vector<FieldBytes> resized = everyArray(set);
    std::size_t next = staying.size(), offset = 0;
    for (const std::size_t bytes : fromRank) {
        next += unpack(resized, next, std::span(arrived).subspan(offset, bytes));
        offset += bytes;
    }
    return counts;
}

template MigrationCounts migrateParticles(const Communicator&, ParticleSet<1>&, const DomainBoxes<1>&);
template MigrationCounts migrateParticles(const Communicator&, ParticleSet<2>&, const DomainBoxes<2>&);
template MigrationCounts migrateParticles(const Communicator&, ParticleSet<3>&, const DomainBoxes<3>&);

}  // namespace sph::parallel
