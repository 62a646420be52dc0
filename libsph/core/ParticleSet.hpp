// Structure-of-arrays particle storage. Positions and global ids are always there; every other
// field is added by the model that needs it (a case that selects no model reading a field never
// allocates it). Owned particles come first, halo copies after them, so a later domain
// decomposition can append halos without touching the owned range; global ids survive reordering.
#pragma once

#include "core/ParticleFields.hpp"
#include "core/Vector.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace sph {

template <int D>
class ParticleSet {
public:
    explicit ParticleSet(std::string name) : name_(std::move(name)) {}
    // The slots point into the fields' map nodes: a copy points into its own.
    ParticleSet(const ParticleSet& other);
    ParticleSet(ParticleSet&& other) noexcept;
    ParticleSet& operator=(const ParticleSet& other);
    ParticleSet& operator=(ParticleSet&& other) noexcept;
    ~ParticleSet() = default;

    const std::string& name() const { return name_; }
    std::size_t size() const { return position.size(); }
    std::size_t ownedCount() const { return owned_; }
    std::size_t haloCount() const { return size() - owned_; }
    void resize(std::size_t owned);  // every field follows; drops the halos
    // Room for `halos` copies after the owned particles (values to be filled by the caller).
    void resizeHalos(std::size_t halos);

    std::vector<Vec<D>> position;
    std::vector<std::int64_t> globalId;

    // The values a field holds: double, Vec<D> or int.
    template <class Value>
    using ValueOf = std::conditional_t<std::is_same_v<Value, VectorValued>, Vec<D>, Value>;

    // Adds a field (or returns the existing one); `written` fields go to the output files (if
    // either call asks). The values are made only for a new field: an integrator asks for its
    // fields every step.
    template <class Value>
    std::vector<ValueOf<Value>>& add(FieldKey<Value> field, const ValueOf<Value>& initial, bool written = true) {
        Field<ValueOf<Value>>* found = find(field);
        if (!found) {
            auto& added = storage<Value>()
                              .emplace(std::string(field.name), Field<ValueOf<Value>>{std::vector<ValueOf<Value>>(size(), initial), false})
                              .first->second;
            if (field.slot >= 0) slots<Value>()[field.slot] = &added;
            found = &added;
        }
        found->written = found->written || written;
        return found->values;
    }

    // Drops a field (nothing where there is none).
    template <class Value>
    void remove(FieldKey<Value> field) {
        if (auto it = storage<Value>().find(field.name); it != storage<Value>().end()) storage<Value>().erase(it);
        if (field.slot >= 0) slots<Value>()[field.slot] = nullptr;
    }

    template <class Value>
    bool has(FieldKey<Value> field) const {
        return find(field) != nullptr;
    }

    // A field that must exist (a programming error otherwise).
    template <class Value>
    std::vector<ValueOf<Value>>& operator[](FieldKey<Value> field) {
        return existing(field).values;
    }
    template <class Value>
    const std::vector<ValueOf<Value>>& operator[](FieldKey<Value> field) const {
        return existing(field).values;
    }

    // A field the case may not have (wall acceleration of fixed walls, say): nullptr without it.
    template <class Value>
    ValueOf<Value>* optionalData(FieldKey<Value> field) {
        auto* found = find(field);
        return found ? found->values.data() : nullptr;
    }
    template <class Value>
    const ValueOf<Value>* optionalData(FieldKey<Value> field) const {
        const auto* found = find(field);
        return found ? found->values.data() : nullptr;
    }

    // new[i] = old[order[i]] for every field.
    void permute(const std::vector<std::uint32_t>& order);
    // The same for a selection: the set then holds order.size() owned particles and no halos.
    void keep(const std::vector<std::uint32_t>& order);

    template <class T>
    struct Field {
        std::vector<T> values;
        bool written;
    };
    template <class T>
    using FieldMap = std::map<std::string, Field<T>, std::less<>>;
    const FieldMap<double>& scalars() const { return scalars_; }
    const FieldMap<Vec<D>>& vectors() const { return vectors_; }
    const FieldMap<int>& integers() const { return integers_; }

private:
    // Of three members, one per value type, the one for Value.
    template <class Value, class Scalars, class Vectors, class Integers>
    static auto& ofType(Scalars& scalars, Vectors& vectors, Integers& integers) {
        if constexpr (std::is_same_v<Value, double>)
            return scalars;
        else if constexpr (std::is_same_v<Value, VectorValued>)
            return vectors;
        else
            return integers;
    }
    template <class Value>
    FieldMap<ValueOf<Value>>& storage() {
        return ofType<Value>(scalars_, vectors_, integers_);
    }
    template <class T>
    using SlotTable = std::array<Field<T>*, libraryFieldNames.size()>;
    template <class Value>
    SlotTable<ValueOf<Value>>& slots() {
        return ofType<Value>(scalarSlots_, vectorSlots_, integerSlots_);
    }
    // A library field by its slot; a user's field by its name. nullptr when the set lacks it.
    template <class Value>
    Field<ValueOf<Value>>* find(FieldKey<Value> field) {
        if (field.slot >= 0) return slots<Value>()[field.slot];
        auto it = storage<Value>().find(field.name);
        return it == storage<Value>().end() ? nullptr : &it->second;
    }
    template <class Value>
    const Field<ValueOf<Value>>* find(FieldKey<Value> field) const {
        return const_cast<ParticleSet*>(this)->find(field);
    }
    template <class Value>
    Field<ValueOf<Value>>& existing(FieldKey<Value> field) const {
        Field<ValueOf<Value>>* found = const_cast<ParticleSet*>(this)->find(field);
        if (!found) throw std::logic_error("particle set '" + name_ + "' has no field '" + std::string(field.name) + "'");
        return *found;
    }
    void fillSlots();
    void resizeArrays(std::size_t count);
    void reorderArrays(const std::vector<std::uint32_t>& order);

    std::string name_;
    std::size_t owned_ = 0;
    FieldMap<double> scalars_;
    FieldMap<Vec<D>> vectors_;
    FieldMap<int> integers_;
    SlotTable<double> scalarSlots_{};
    SlotTable<Vec<D>> vectorSlots_{};
    SlotTable<int> integerSlots_{};
};

}  // namespace sph
