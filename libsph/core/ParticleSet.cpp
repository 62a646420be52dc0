#include "core/ParticleSet.hpp"

#include <stdexcept>

namespace sph {

namespace {

template <class T>
void permuteValues(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
    std::vector<T> reordered(values.size());
    for (std::size_t i = 0; i < order.size(); ++i) reordered[i] = values[order[i]];
    values.swap(reordered);
}

template <class Map>
auto& fieldOf(Map& fields, const std::string& set, const std::string& field) {
    auto it = fields.find(field);
    if (it == fields.end()) throw std::logic_error("particle set '" + set + "' has no field '" + field + "'");
    return it->second.values;
}

}  // namespace

template <int D>
void ParticleSet<D>::resize(std::size_t owned) {
    owned_ = owned;
    position.resize(owned, Vec<D>::Zero());
    globalId.resize(owned, -1);
    for (auto& [name, f] : scalars_) f.values.resize(owned, 0.0);
    for (auto& [name, f] : vectors_) f.values.resize(owned, Vec<D>::Zero());
    for (auto& [name, f] : integers_) f.values.resize(owned, 0);
}

// Adds a field of `initial` values, or returns the existing one (written if either asks). The
// values are made only for a new field: an integrator asks for its fields every step.
template <class Map, class T>
auto& addField(Map& fields, const std::string& field, std::size_t size, const T& initial, bool written) {
    auto it = fields.find(field);
    if (it == fields.end()) return fields.emplace(field, typename Map::mapped_type{std::vector<T>(size, initial), written}).first->second.values;
    it->second.written = it->second.written || written;
    return it->second.values;
}

template <int D>
std::vector<double>& ParticleSet<D>::addScalar(const std::string& field, double initial, bool written) {
    return addField(scalars_, field, size(), initial, written);
}

template <int D>
std::vector<Vec<D>>& ParticleSet<D>::addVector(const std::string& field, const Vec<D>& initial, bool written) {
    return addField(vectors_, field, size(), initial, written);
}

template <int D>
std::vector<int>& ParticleSet<D>::addInteger(const std::string& field, int initial, bool written) {
    return addField(integers_, field, size(), initial, written);
}

template <int D>
std::vector<double>& ParticleSet<D>::scalar(const std::string& field) {
    return fieldOf(scalars_, name_, field);
}
template <int D>
const std::vector<double>& ParticleSet<D>::scalar(const std::string& field) const {
    return fieldOf(scalars_, name_, field);
}
template <int D>
std::vector<Vec<D>>& ParticleSet<D>::vector(const std::string& field) {
    return fieldOf(vectors_, name_, field);
}
template <int D>
const std::vector<Vec<D>>& ParticleSet<D>::vector(const std::string& field) const {
    return fieldOf(vectors_, name_, field);
}
template <int D>
std::vector<int>& ParticleSet<D>::integer(const std::string& field) {
    return fieldOf(integers_, name_, field);
}
template <int D>
const std::vector<int>& ParticleSet<D>::integer(const std::string& field) const {
    return fieldOf(integers_, name_, field);
}

template <int D>
void ParticleSet<D>::permute(const std::vector<std::uint32_t>& order) {
    permuteValues(position, order);
    permuteValues(globalId, order);
    for (auto& [name, f] : scalars_) permuteValues(f.values, order);
    for (auto& [name, f] : vectors_) permuteValues(f.values, order);
    for (auto& [name, f] : integers_) permuteValues(f.values, order);
}

template class ParticleSet<1>;
template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace sph
