// A particle set's per-particle arrays seen as bytes, so that one loop packs any mix of them into
// a message and unpacks it: a migration carries every array, a halo refresh a chosen few. A
// message holds, array by array, the values of the particles listed.
#pragma once

#include "core/ParticleSet.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sph {

struct FieldBytes {
    std::byte* data;
    std::size_t bytesPerParticle;
};

template <class T>
FieldBytes bytesOf(std::vector<T>& values) {
    return {reinterpret_cast<std::byte*>(values.data()), sizeof(T)};
}

// Global ids, positions, then every field by type and name: the same order on every rank, since
// the ranks' sets hold the same fields. Valid until the set is next resized.
template <int D>
std::vector<FieldBytes> everyArray(ParticleSet<D>& set);

std::size_t bytesPerParticle(const std::vector<FieldBytes>& arrays);

// Appends the values of `particles` (indices into the arrays) to `message`.
void pack(const std::vector<FieldBytes>& arrays, std::span<const std::uint32_t> particles, std::vector<std::byte>& message);

// Writes a message of `pack` to the particles first, first + 1, ...; returns how many it held.
std::size_t unpack(const std::vector<FieldBytes>& arrays, std::size_t first, std::span<const std::byte> message);

// The same to the particles `places` (as many as the message holds).
void unpack(const std::vector<FieldBytes>& arrays, std::span<const std::uint32_t> places, std::span<const std::byte> message);

}  // namespace sph
