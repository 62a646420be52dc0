#include "core/FieldBytes.hpp"

#include <cstring>
#include <stdexcept>

namespace sph {

template <int D>
std::vector<FieldBytes> everyArray(ParticleSet<D>& set) {
    std::vector<FieldBytes> arrays{bytesOf(set.globalId), bytesOf(set.position)};
    for (const auto& [name, field] : set.scalars()) arrays.push_back(bytesOf(set[ScalarField(name)]));
    for (const auto& [name, field] : set.vectors()) arrays.push_back(bytesOf(set[VectorField(name)]));
    for (const auto& [name, field] : set.integers()) arrays.push_back(bytesOf(set[IntegerField(name)]));
    return arrays;
}

std::size_t bytesPerParticle(const std::vector<FieldBytes>& arrays) {
    std::size_t bytes = 0;
    for (const FieldBytes& array : arrays) bytes += array.bytesPerParticle;
    return bytes;
}

void pack(const std::vector<FieldBytes>& arrays, std::span<const std::uint32_t> particles, std::vector<std::byte>& message) {
    std::size_t at = message.size();
    message.resize(at + particles.size() * bytesPerParticle(arrays));
    for (const FieldBytes& array : arrays)
        for (const std::uint32_t particle : particles) {
            std::memcpy(message.data() + at, array.data + particle * array.bytesPerParticle, array.bytesPerParticle);
            at += array.bytesPerParticle;
        }
}

std::size_t unpack(const std::vector<FieldBytes>& arrays, std::size_t first, std::span<const std::byte> message) {
    const std::size_t record = bytesPerParticle(arrays);
    if (message.size() % record != 0)
        throw std::logic_error("a particle message of " + std::to_string(message.size()) + " bytes is no whole number of " + std::to_string(record) +
                               "-byte particles: the ranks' sets hold different fields");
    const std::size_t count = message.size() / record;
    if (count == 0) return 0;  // an empty message may have no storage at all
    const std::byte* from = message.data();
    for (const FieldBytes& array : arrays) {
        std::memcpy(array.data + first * array.bytesPerParticle, from, count * array.bytesPerParticle);
        from += count * array.bytesPerParticle;
    }
    return count;
}

void unpack(const std::vector<FieldBytes>& arrays, std::span<const std::uint32_t> places, std::span<const std::byte> message) {
    if (message.size() != places.size() * bytesPerParticle(arrays))
        throw std::logic_error("a particle message of " + std::to_string(message.size()) + " bytes does not fill " + std::to_string(places.size()) +
                               " places: the ranks' sets hold different fields");
    const std::byte* from = message.data();
    for (const FieldBytes& array : arrays)
        for (const std::uint32_t place : places) {
            std::memcpy(array.data + place * array.bytesPerParticle, from, array.bytesPerParticle);
            from += array.bytesPerParticle;
        }
}

template std::vector<FieldBytes> everyArray(ParticleSet<1>&);
template std::vector<FieldBytes> everyArray(ParticleSet<2>&);
template std::vector<FieldBytes> everyArray(ParticleSet<3>&);

}  // namespace sph
