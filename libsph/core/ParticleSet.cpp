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
