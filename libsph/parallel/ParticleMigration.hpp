// Moves each owned particle to the rank whose box holds it, with every field and its global id.
// Halo copies are dropped first (they are rebuilt after a migration). The particles that stay
// keep their order; those that arrive follow them, by source rank, each source's in its order.
#pragma once

#include "core/ParticleSet.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DomainBoxes.hpp"

#include <cstddef>

namespace sph::parallel {

struct MigrationCounts {
    std::size_t sent = 0;
    std::size_t received = 0;
};

// Collective. Stops every rank (FatalError) where a particle lies in no box (a non-finite
// position), naming the set and the particle's global id.
template <int D>
MigrationCounts migrateParticles(const Communicator& ranks, ParticleSet<D>& set, const DomainBoxes<D>& boxes);

}  // namespace sph::parallel
