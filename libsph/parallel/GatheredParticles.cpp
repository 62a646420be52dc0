#include "parallel/GatheredParticles.hpp"

#include "core/FieldBytes.hpp"
#include "io/ParticleState.hpp"

#include <numeric>
#include <span>

namespace sph::parallel {

template <int D>
void gatherToFirst(const Communicator& ranks, ParticleSet<D>& set) {
    std::vector<std::uint32_t> all(set.size());
    std::iota(all.begin(), all.end(), 0u);
    std::vector<std::byte> mine;
    pack(everyArray(set), all, mine);
    std::vector<std::size_t> fromRank;
    const std::vector<std::byte> gathered = ranks.gatherToFirst(mine, fromRank);
    if (ranks.rank() != 0) {
        set.resize(0);
        return;
    }
    const std::size_t record = bytesPerParticle(everyArray(set));
    set.resize(record > 0 ? gathered.size() / record : 0);
    const std::vector<FieldBytes> arrays = everyArray(set);
    std::size_t next = 0, offset = 0;
    for (const std::size_t bytes : fromRank) {
        next += unpack(arrays, next, std::span(gathered).subspan(offset, bytes));
        offset += bytes;
    }
    set.permute(serialOrder(set));
}

#ifdef SPHKIT_HAS_2D
template void gatherToFirst<2>(const Communicator&, ParticleSet<2>&);
#endif
#ifdef SPHKIT_HAS_3D
template void gatherToFirst<3>(const Communicator&, ParticleSet<3>&);
#endif

}  // namespace sph::parallel
