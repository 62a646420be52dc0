#include "core/ParticleSet.hpp"

#include <stdexcept>

namespace sph {

namespace {

template <class T>
void permuteValues(std::vector<T>& values, const std::vector<std::uint32_t>& order) {
    std::vector<T> reordered(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) reordered[i] = values[order[i]];
    values.swap(reordered);
}

template <class Map, class Table>
void pointSlotsInto(Map& fields, Table& slots) {
    slots.fill(nullptr);
    for (auto& [name, field] : fields)
        if (const int slot = librarySlot(name); slot >= 0) slots[slot] = &field;
}

}  // namespace

template <int D>
void ParticleSet<D>::fillSlots() {
    pointSlotsInto(scalars_, scalarSlots_);
    pointSlotsInto(vectors_, vectorSlots_);
    pointSlotsInto(integers_, integerSlots_);
}

template <int D>
ParticleSet<D>::ParticleSet(const ParticleSet& other)
    : position(other.position),
      globalId(other.globalId),
      name_(other.name_),
      owned_(other.owned_),
      scalars_(other.scalars_),
      vectors_(other.vectors_),
      integers_(other.integers_) {
    fillSlots();
}

template <int D>
ParticleSet<D>::ParticleSet(ParticleSet&& other) noexcept
    : position(std::move(other.position)),
      globalId(std::move(other.globalId)),
      name_(std::move(other.name_)),
      owned_(other.owned_),
      scalars_(std::move(other.scalars_)),
      vectors_(std::move(other.vectors_)),
      integers_(std::move(other.integers_)) {
    fillSlots();
    other.fillSlots();
}

template <int D>
ParticleSet<D>& ParticleSet<D>::operator=(const ParticleSet& other) {
    if (this != &other) *this = ParticleSet(other);
    return *this;
}

template <int D>
ParticleSet<D>& ParticleSet<D>::operator=(ParticleSet&& other) noexcept {
    if (this == &other) return *this;
    position = std::move(other.position);
    globalId = std::move(other.globalId);
    name_ = std::move(other.name_);
    owned_ = other.owned_;
    scalars_ = std::move(other.scalars_);
    vectors_ = std::move(other.vectors_);
    integers_ = std::move(other.integers_);
    fillSlots();
    other.fillSlots();
    return *this;
}

template <int D>
void ParticleSet<D>::resizeArrays(std::size_t count) {
    position.resize(count, Vec<D>::Zero());
    globalId.resize(count, -1);
    for (auto& [name, f] : scalars_) f.values.resize(count, 0.0);
    for (auto& [name, f] : vectors_) f.values.resize(count, Vec<D>::Zero());
    for (auto& [name, f] : integers_) f.values.resize(count, 0);
}

template <int D>
void ParticleSet<D>::resize(std::size_t owned) {
    owned_ = owned;
    resizeArrays(owned);
}

template <int D>
void ParticleSet<D>::resizeHalos(std::size_t halos) {
    resizeArrays(owned_ + halos);
}

template <int D>
void ParticleSet<D>::reorderArrays(const std::vector<std::uint32_t>& order) {
    permuteValues(position, order);
    permuteValues(globalId, order);
    for (auto& [name, f] : scalars_) permuteValues(f.values, order);
    for (auto& [name, f] : vectors_) permuteValues(f.values, order);
    for (auto& [name, f] : integers_) permuteValues(f.values, order);
}

template <int D>
void ParticleSet<D>::permute(const std::vector<std::uint32_t>& order) {
    if (order.size() != size()) throw std::logic_error("a permutation of '" + name_ + "' must list every particle once");
    reorderArrays(order);
}

template <int D>
void ParticleSet<D>::keep(const std::vector<std::uint32_t>& order) {
    reorderArrays(order);
    owned_ = order.size();
}

template class ParticleSet<1>;
template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace sph
