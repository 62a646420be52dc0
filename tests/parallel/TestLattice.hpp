// Particles for the tests of the decomposition: a lattice whose every field is a function of the
// global id, so that any rank can check any particle it holds, and what every rank can compute
// from all particles gathered.
#pragma once

#include "core/ParticleSet.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DomainBoxes.hpp"
#include "parallel/RcbPartition.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace sph::parallel::test {

inline constexpr ScalarField tracer{"tracer"};  // a user's field travels like the library's

// Every field a function of the global id, so that any rank can check any particle.
template <int D>
Vec<D> velocityOf(std::int64_t id) {
    Vec<D> v;
    for (int d = 0; d < D; ++d) v[d] = static_cast<double>(id) * (d + 1) - 0.25;
    return v;
}
inline double densityOf(std::int64_t id) { return 1000.0 + 0.001 * static_cast<double>(id); }
inline int patchOf(std::int64_t id) { return static_cast<int>(id % 7); }

// A lattice of side^D points (spacing `spacing`, jittered by up to `jitter` of it), all owned by
// rank 0: the other ranks start empty, as they do before the first partition.
template <int D>
ParticleSet<D> latticeOnRankZero(const Communicator& ranks, int side, double spacing, double jitter) {
    ParticleSet<D> set("fluid");
    set.add(fields::density, 0.0);
    set.add(fields::velocity, Vec<D>::Zero());
    set.add(fields::patch, 0);
    set.add(tracer, 0.0);
    if (ranks.rank() != 0) return set;
    std::size_t count = 1;
    for (int d = 0; d < D; ++d) count *= static_cast<std::size_t>(side);
    set.resize(count);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> offset(-jitter * spacing, jitter * spacing);
    for (std::size_t i = 0; i < count; ++i) {
        std::size_t rest = i;
        for (int d = 0; d < D; ++d) {
            set.position[i][d] = (static_cast<double>(rest % side) + 0.5) * spacing + offset(random);
            rest /= static_cast<std::size_t>(side);
        }
        const auto id = static_cast<std::int64_t>(i);
        set.globalId[i] = id;
        set[fields::density][i] = densityOf(id);
        set[fields::velocity][i] = velocityOf<D>(id);
        set[fields::patch][i] = patchOf(id);
        set[tracer][i] = 0.5 * static_cast<double>(id);
    }
    return set;
}

template <int D>
DomainBoxes<D> partitionSet(const Communicator& ranks, const ParticleSet<D>& set, double length, const std::type_identity_t<Vec<D>>& period) {
    const std::vector<double> weights(set.ownedCount(), 1.0);
    return partitionByRcb<D>(ranks, std::span(set.position.data(), set.ownedCount()), weights, Vec<D>::Zero(), Vec<D>::Constant(length), period);
}

// Every rank's owned (id, position), gathered on every rank: the brute force's input.
template <int D>
std::map<std::int64_t, Vec<D>> gatherOwned(const Communicator& ranks, const ParticleSet<D>& set) {
    const auto mine = static_cast<int>(set.ownedCount());
    std::vector<int> counts(static_cast<std::size_t>(ranks.size())), offsets(counts.size());
    MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, ranks.handle());
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) offsets[r] = std::exchange(total, total + counts[r]);
    std::vector<std::int64_t> ids(static_cast<std::size_t>(total));
    MPI_Allgatherv(set.globalId.data(), mine, MPI_INT64_T, ids.data(), counts.data(), offsets.data(), MPI_INT64_T, ranks.handle());
    for (int& c : counts) c *= D;
    for (int& o : offsets) o *= D;
    std::vector<double> xyz(static_cast<std::size_t>(total) * D);
    MPI_Allgatherv(set.position.data(), mine * D, MPI_DOUBLE, xyz.data(), counts.data(), offsets.data(), MPI_DOUBLE, ranks.handle());
    std::map<std::int64_t, Vec<D>> all;
    for (std::size_t i = 0; i < ids.size(); ++i) all.emplace(ids[i], Eigen::Map<const Vec<D>>(&xyz[i * D]));
    EXPECT_EQ(all.size(), ids.size()) << "a global id is owned twice";
    return all;
}

// The particles [first, last) whose fields are not those of their id.
template <int D>
inline int wrongFields(const ParticleSet<D>& set, std::size_t first, std::size_t last) {
    int wrong = 0;
    for (std::size_t i = first; i < last; ++i) {
        const std::int64_t id = set.globalId[i];
        wrong += set[fields::density][i] != densityOf(id) || set[fields::velocity][i] != velocityOf<D>(id) || set[fields::patch][i] != patchOf(id) ||
                 set[tracer][i] != 0.5 * static_cast<double>(id);
    }
    return wrong;
}

}  // namespace sph::parallel::test
