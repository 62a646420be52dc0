// Structure-of-arrays particle storage. Positions and global ids are always there; every other
// field is added by the model that needs it (a case that selects no model reading a field never
// allocates it). Owned particles come first, halo copies after them, so a later domain
// decomposition can append halos without touching the owned range; global ids survive reordering.
#pragma once

#include "core/ParticleFields.hpp"
#include "core/Vector.hpp"

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

    const std::string& name() const { return name_; }
    std::size_t size() const { return position.size(); }
    std::size_t ownedCount() const { return owned_; }
    void resize(std::size_t owned);  // every field follows; no halos yet

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
        auto& fields = storage<Value>();
        auto it = fields.find(field.name);
        if (it == fields.end())
            it = fields.emplace(std::string(field.name), Field<ValueOf<Value>>{std::vector<ValueOf<Value>>(size(), initial), false}).first;
        it->second.written = it->second.written || written;
        return it->second.values;
    }

    template <class Value>
    bool has(FieldKey<Value> field) const {
        return storage<Value>().count(field.name) != 0;
    }

    // A field that must exist (a programming error otherwise).
    template <class Value>
    std::vector<ValueOf<Value>>& operator[](FieldKey<Value> field) {
        return valuesOf(storage<Value>(), field.name);
    }
    template <class Value>
    const std::vector<ValueOf<Value>>& operator[](FieldKey<Value> field) const {
        return valuesOf(storage<Value>(), field.name);
    }

    // A field the case may not have (wall acceleration of fixed walls, say): nullptr without it.
    template <class Value>
    ValueOf<Value>* optionalData(FieldKey<Value> field) {
        auto it = storage<Value>().find(field.name);
        return it == storage<Value>().end() ? nullptr : it->second.values.data();
    }
    template <class Value>
    const ValueOf<Value>* optionalData(FieldKey<Value> field) const {
        auto it = storage<Value>().find(field.name);
        return it == storage<Value>().end() ? nullptr : it->second.values.data();
    }

    // new[i] = old[order[i]] for every field.
    void permute(const std::vector<std::uint32_t>& order);

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
    template <class Value>
    FieldMap<ValueOf<Value>>& storage() {
        if constexpr (std::is_same_v<Value, double>)
            return scalars_;
        else if constexpr (std::is_same_v<Value, VectorValued>)
            return vectors_;
        else
            return integers_;
    }
    template <class Value>
    const FieldMap<ValueOf<Value>>& storage() const {
        return const_cast<ParticleSet*>(this)->storage<Value>();
    }
    template <class Map>
    auto& valuesOf(Map& fields, std::string_view field) const {
        auto it = fields.find(field);
        if (it == fields.end()) throw std::logic_error("particle set '" + name_ + "' has no field '" + std::string(field) + "'");
        return it->second.values;
    }

    std::string name_;
    std::size_t owned_ = 0;
    FieldMap<double> scalars_;
    FieldMap<Vec<D>> vectors_;
    FieldMap<int> integers_;
};

}  // namespace sph
