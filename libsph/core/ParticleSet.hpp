// Structure-of-arrays particle storage. Positions and global ids are always there; every other
// field is added by the model that needs it (a case that selects no model reading a field never
// allocates it). Owned particles come first, halo copies after them, so a later domain
// decomposition can append halos without touching the owned range; global ids survive reordering.
#pragma once

#include "core/Vector.hpp"

#include <cstdint>
#include <map>
#include <string>
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

    // Adds a field (or returns the existing one); `written` fields go to the output files.
    std::vector<double>& addScalar(const std::string& field, double initial, bool written = true);
    std::vector<Vec<D>>& addVector(const std::string& field, const Vec<D>& initial, bool written = true);
    std::vector<int>& addInteger(const std::string& field, int initial, bool written = true);

    bool hasScalar(const std::string& field) const { return scalars_.count(field) != 0; }
    bool hasVector(const std::string& field) const { return vectors_.count(field) != 0; }
    bool hasInteger(const std::string& field) const { return integers_.count(field) != 0; }

    // Access to a field that must exist (a programming error otherwise).
    std::vector<double>& scalar(const std::string& field);
    const std::vector<double>& scalar(const std::string& field) const;
    std::vector<Vec<D>>& vector(const std::string& field);
    const std::vector<Vec<D>>& vector(const std::string& field) const;
    std::vector<int>& integer(const std::string& field);
    const std::vector<int>& integer(const std::string& field) const;

    // new[i] = old[order[i]] for every field.
    void permute(const std::vector<std::uint32_t>& order);

    template <class T>
    struct Field {
        std::vector<T> values;
        bool written;
    };
    const std::map<std::string, Field<double>>& scalars() const { return scalars_; }
    const std::map<std::string, Field<Vec<D>>>& vectors() const { return vectors_; }
    const std::map<std::string, Field<int>>& integers() const { return integers_; }

private:
    std::string name_;
    std::size_t owned_ = 0;
    std::map<std::string, Field<double>> scalars_;
    std::map<std::string, Field<Vec<D>>> vectors_;
    std::map<std::string, Field<int>> integers_;
};

}  // namespace sph
