// The domain decomposition on the ranks mpirun starts (CTest runs it on 1, 2, 3 and 4): Zoltan's
// boxes, migration and halo lists, each checked against what every rank can compute alone from
// all particles gathered (a brute-force search). Each test ends its collectives before it
// asserts, so that a failure on one rank cannot leave the others waiting.
#include "core/FatalError.hpp"
#include "core/ParticleSet.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/CostBalance.hpp"
#include "parallel/HaloExchange.hpp"
#include "parallel/ParticleMigration.hpp"
#include "parallel/RcbPartition.hpp"
#include "parallel/TestLattice.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace sph::parallel {
namespace {

using namespace test;

template <int D>
double nearestImageDistance(Vec<D> r, const Vec<D>& period) {
    for (int d = 0; d < D; ++d)
        if (period[d] > 0.0) r[d] -= period[d] * std::nearbyint(r[d] / period[d]);
    return r.norm();
}

template <class Dimension>
class Decomposition : public testing::Test {};
using Dimensions = testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(Decomposition, Dimensions);

TYPED_TEST(Decomposition, BoxesTileSpaceAndShareALatticeEvenly) {
    constexpr int D = TypeParam::value;
    const Communicator ranks;
    const int side = D == 2 ? 24 : 10;
    ParticleSet<D> set = latticeOnRankZero<D>(ranks, side, 0.01, 0.0);
    const DomainBoxes<D> boxes = partitionSet(ranks, set, side * 0.01, Vec<D>::Zero());
    ASSERT_EQ(boxes.ranks(), ranks.size());
    // Every point, and the points on and beside every face, lies in exactly one box.
    int notInExactlyOne = 0;
    for (int r = 0; r < boxes.ranks(); ++r)
        for (const Vec<D>& corner : {boxes.box(r).lower, boxes.box(r).upper}) {
            for (const double nudge : {-1e-12, 0.0, 1e-12}) {
                Vec<D> x = corner.cwiseMax(Vec<D>::Constant(-1.0)).cwiseMin(Vec<D>::Constant(2.0)).array() + nudge;
                int holders = 0;
                for (int q = 0; q < boxes.ranks(); ++q) {
                    bool inside = true;
                    for (int d = 0; d < D; ++d) inside = inside && boxes.box(q).lower[d] <= x[d] && x[d] < boxes.box(q).upper[d];
                    holders += inside;
                }
                notInExactlyOne += holders != 1 || boxes.ownerOf(x) < 0;
            }
        }
    migrateParticles(ranks, set, boxes);
    const double imbalance = loadImbalance(ranks, static_cast<double>(set.ownedCount()));
    EXPECT_EQ(notInExactlyOne, 0);
    // RCB's cuts fall between lattice planes: a rank is off its share by at most one plane of
    // the lattice per cut it borders (24 points in 2D, 100 in 3D, of 576 and 1000).
    const double share = std::pow(side, D) / ranks.size(), plane = std::pow(side, D - 1);
    EXPECT_LE(imbalance, 1.0 + 2.0 * plane / share) << "shares of " << share;
}

TYPED_TEST(Decomposition, MigrationMovesEveryParticleToItsBoxWithEveryField) {
    constexpr int D = TypeParam::value;
    const Communicator ranks;
    const int side = D == 2 ? 20 : 8;
    ParticleSet<D> set = latticeOnRankZero<D>(ranks, side, 0.01, 0.3);
    const std::int64_t total = ranks.sumOverRanks(static_cast<std::int64_t>(set.ownedCount()));
    const DomainBoxes<D> boxes = partitionSet(ranks, set, side * 0.01, Vec<D>::Zero());
    for (int round = 0; round < 2; ++round) {
        const MigrationCounts counts = migrateParticles(ranks, set, boxes);
        const std::int64_t sent = ranks.sumOverRanks(static_cast<std::int64_t>(counts.sent));
        const std::int64_t received = ranks.sumOverRanks(static_cast<std::int64_t>(counts.received));
        const std::map<std::int64_t, Vec<D>> all = gatherOwned(ranks, set);
        int outsideMyBox = 0;
        for (std::size_t i = 0; i < set.ownedCount(); ++i) outsideMyBox += boxes.ownerOf(set.position[i]) != ranks.rank();
        EXPECT_EQ(sent, received);
        EXPECT_EQ(static_cast<std::int64_t>(all.size()), total);
        EXPECT_TRUE(all.empty() || (all.begin()->first == 0 && all.rbegin()->first == total - 1));
        EXPECT_EQ(outsideMyBox, 0);
        EXPECT_EQ(wrongFields(set, 0, set.ownedCount()), 0);
        // Then every particle moves a third of the box diagonal: many cross a cut.
        for (std::size_t i = 0; i < set.ownedCount(); ++i) set.position[i].array() += 0.33 * side * 0.01;
    }
}

TYPED_TEST(Decomposition, HaloListsHoldEveryParticleWithinTheWidthAndNoOther) {
    constexpr int D = TypeParam::value;
    const Communicator ranks;
    const int side = D == 2 ? 24 : 9;
    const double spacing = 0.01, length = side * spacing, width = 2.9 * spacing;
    for (const bool periodicX : {false, true}) {
        Vec<D> period = Vec<D>::Zero();
        if (periodicX) period[0] = length;
        ParticleSet<D> set = latticeOnRankZero<D>(ranks, side, spacing, 0.45);
        for (auto& x : set.position) x[0] -= length * std::floor(x[0] / length);  // jitter can leave the period
        const DomainBoxes<D> boxes = partitionSet(ranks, set, length, period);
        migrateParticles(ranks, set, boxes);
        const std::map<std::int64_t, Vec<D>> all = gatherOwned(ranks, set);
        const HaloExchange<D> halos(ranks, set, boxes, width);
        const std::int64_t sent = ranks.sumOverRanks(static_cast<std::int64_t>(halos.sentCount()));
        const std::int64_t received = ranks.sumOverRanks(static_cast<std::int64_t>(set.haloCount()));

        std::map<std::int64_t, std::size_t> here;  // id -> place, owned and halo
        int duplicates = 0, wrongPositions = 0;
        for (std::size_t i = 0; i < set.size(); ++i) {
            duplicates += !here.emplace(set.globalId[i], i).second;
            const auto found = all.find(set.globalId[i]);
            wrongPositions += found == all.end() || found->second != set.position[i];
        }
        // Brute force 1: every particle within the width of an owned one (nearest image) is here.
        int missing = 0;
        for (std::size_t i = 0; i < set.ownedCount(); ++i)
            for (const auto& [id, x] : all) missing += nearestImageDistance<D>(x - set.position[i], period) <= width && !here.contains(id);
        // Brute force 2: the halos are exactly the others' particles within the width of this box.
        int expectedHalos = 0, unexpected = 0;
        for (const auto& [id, x] : all) {
            const bool mine = boxes.ownerOf(x) == ranks.rank();
            expectedHalos += !mine && boxes.distanceToBox(x, ranks.rank()) <= width;
        }
        for (std::size_t i = set.ownedCount(); i < set.size(); ++i)
            unexpected += boxes.ownerOf(set.position[i]) == ranks.rank() || boxes.distanceToBox(set.position[i], ranks.rank()) > width;
        EXPECT_EQ(sent, received);
        EXPECT_EQ(duplicates, 0);
        EXPECT_EQ(wrongPositions, 0);
        EXPECT_EQ(missing, 0) << (periodicX ? "periodic in x" : "not periodic");
        EXPECT_EQ(static_cast<int>(set.haloCount()), expectedHalos);
        EXPECT_EQ(unexpected, 0);
        EXPECT_EQ(wrongFields(set, 0, set.size()), 0);
        if (ranks.size() > 1 && periodicX) {
            EXPECT_GT(received, 0);
        }
    }
}

TYPED_TEST(Decomposition, ARefreshSendsTheOwnersNewValuesOfTheNamedFieldsOnly) {
    constexpr int D = TypeParam::value;
    const Communicator ranks;
    const int side = D == 2 ? 16 : 7;
    ParticleSet<D> set = latticeOnRankZero<D>(ranks, side, 0.01, 0.2);
    const DomainBoxes<D> boxes = partitionSet(ranks, set, side * 0.01, Vec<D>::Zero());
    migrateParticles(ranks, set, boxes);
    const HaloExchange<D> halos(ranks, set, boxes, 0.03);
    for (std::size_t i = 0; i < set.ownedCount(); ++i) {
        set[fields::density][i] = 2.0 * densityOf(set.globalId[i]);
        set[fields::velocity][i] = -velocityOf<D>(set.globalId[i]);
        set.position[i].array() += 1e-3;
        set[tracer][i] = -1.0;
    }
    halos.refresh(set, fields::density, fields::velocity);
    halos.refreshPositions(set);
    const std::map<std::int64_t, Vec<D>> all = gatherOwned(ranks, set);
    int stale = 0, touched = 0;
    for (std::size_t i = set.ownedCount(); i < set.size(); ++i) {
        const std::int64_t id = set.globalId[i];
        stale += set[fields::density][i] != 2.0 * densityOf(id) || set[fields::velocity][i] != -velocityOf<D>(id) || set.position[i] != all.at(id);
        touched += set[tracer][i] != 0.5 * static_cast<double>(id);
    }
    EXPECT_EQ(stale, 0);
    EXPECT_EQ(touched, 0);
}

TEST(Decomposition, ARankThatOwnsNoParticleTakesPartInEveryStep) {
    const Communicator ranks;
    ParticleSet<2> set = latticeOnRankZero<2>(ranks, 2, 0.01, 0.0);  // 4 particles, 1 to 4 ranks
    if (ranks.rank() == 0) set.keep({0, 1});                         // two particles: with 3 or 4 ranks, some own none
    const DomainBoxes<2> boxes = partitionSet(ranks, set, 0.02, Vec<2>::Zero());
    migrateParticles(ranks, set, boxes);
    const HaloExchange<2> halos(ranks, set, boxes, 0.015);
    halos.refresh(set, fields::density);
    const std::int64_t owned = ranks.sumOverRanks(static_cast<std::int64_t>(set.ownedCount()));
    const std::int64_t empty = ranks.sumOverRanks(set.ownedCount() == 0 ? 1 : 0);
    EXPECT_EQ(owned, 2);
    EXPECT_EQ(wrongFields(set, 0, set.size()), 0);
    if (ranks.size() > 2) {
        EXPECT_GE(empty, 1);
    }
}

// Rank r reports r + 1 seconds of work on particles weighing 10: on P ranks the slowest is
// 2P / (P + 1) times the mean, and r's seconds per unit weight against the mean's are
// ((r + 1) / 10) / (P (P + 1) / 2 / (10 P)) = 2 (r + 1) / (P + 1). Checks wait 100 steps, and the
// seconds count from the last check.
TEST(Decomposition, CostBalanceWeighsEachRankByItsMeasuredCost) {
    const Communicator ranks;
    const double P = ranks.size(), r = ranks.rank();
    CostBalance balance(1.1, 0);
    const auto early = balance.check(ranks, 99, r + 1.0, 10.0);
    const auto first = balance.check(ranks, 100, r + 1.0, 10.0);
    // The next 100 steps: every rank 7 s more, balanced.
    const auto balanced = balance.check(ranks, 200, r + 8.0, 10.0);
    const auto never = CostBalance(0.0, 0).check(ranks, 100, r + 1.0, 10.0);
    EXPECT_FALSE(early);
    EXPECT_FALSE(balanced);
    EXPECT_FALSE(never);
    if (ranks.size() == 1) {
        EXPECT_FALSE(first);
    } else {
        ASSERT_TRUE(first);
        EXPECT_DOUBLE_EQ(first->imbalance, 2.0 * P / (P + 1.0));
        EXPECT_DOUBLE_EQ(first->weightPerParticle, 2.0 * (r + 1.0) / (P + 1.0));
    }
}

TEST(Decomposition, AFailureOnOneRankStopsEveryRankWithItsMessage) {
    const Communicator ranks;
    const int failing = ranks.size() - 1;
    std::string caught;
    try {
        ranks.stopIfAnyFailed(ranks.rank() == failing ? std::optional<std::string>("density is NaN at particle 17") : std::nullopt);
    } catch (const FatalError& error) {
        caught = error.what();
    }
    EXPECT_EQ(caught, "rank " + std::to_string(failing) + " of " + std::to_string(ranks.size()) + ": density is NaN at particle 17");
    // The ranks are still in step: the next collective completes.
    EXPECT_EQ(ranks.sumOverRanks(1), ranks.size());
    EXPECT_NO_THROW(ranks.stopIfAnyFailed(std::nullopt));
}

TEST(Decomposition, AParticleInNoBoxStopsEveryRankNamingIt) {
    const Communicator ranks;
    ParticleSet<2> set = latticeOnRankZero<2>(ranks, 6, 0.01, 0.0);
    const DomainBoxes<2> boxes = partitionSet(ranks, set, 0.06, Vec<2>::Zero());
    if (ranks.rank() == 0) set.position[5][1] = std::nan("");
    std::string caught;
    try {
        migrateParticles(ranks, set, boxes);
    } catch (const FatalError& error) {
        caught = error.what();
    }
    EXPECT_EQ(caught, "rank 0 of " + std::to_string(ranks.size()) + ": particle 5 of 'fluid' lies in no rank's box");
}

}  // namespace
}  // namespace sph::parallel
