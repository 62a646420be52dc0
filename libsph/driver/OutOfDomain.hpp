// What becomes of a fluid particle that leaves the domain, system/controlDict's `outOfDomain`:
//
//     outOfDomain     stop;       // the default: the run stops as blown up, naming the particle
//     outOfDomain     remove;     // the particle is removed and the run goes on
//
// `remove` is DualSPHysics' exclusion of particles that leave the domain: a splash over an open
// tank's wall need not end a run. Each step that removes any prints a line with its count and
// the count so far. A particle that leaves through a wall is removed all the same: count leaks
// with `wallPenetrations`.
#pragma once

#include "core/ParticleSet.hpp"
#include "io/Dictionary.hpp"

#include <cstdint>
#include <vector>

namespace sph {

enum class OutOfDomain { Stop, Remove };

// FatalError naming the keyword for a value other than stop or remove.
OutOfDomain readOutOfDomain(const Dictionary& controlDict);

// The places, in storage order, of the fluid particles whose finite position lies outside
// [domainMin, domainMax] (a non-finite one is the blow-up check's).
template <int D>
std::vector<std::uint32_t> fluidOutside(const ParticleSet<D>& fluid, const Vec<D>& domainMin, const Vec<D>& domainMax);

// Keeps every fluid particle but those at `places` (ascending), in their order.
template <int D>
void removeFluid(ParticleSet<D>& fluid, const std::vector<std::uint32_t>& places);

// The line a step that removed particles prints.
void reportRemoved(long step, double t, std::int64_t removed, std::int64_t removedSoFar);

}  // namespace sph
