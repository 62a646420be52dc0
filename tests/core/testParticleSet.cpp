// The particle store: fields by typed key, optional fields, reordering.
#include "core/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using sph::ParticleSet;
using sph::Vec;
namespace fields = sph::fields;

// A field is asked for by its key, never by a string: a misspelt name does not compile, and a
// key of one type cannot read a field of another.
template <class Name>
constexpr bool readableBy = requires(ParticleSet<2>& set, Name name) {
    set[name];
};
template <class Name>
constexpr bool addableBy = requires(ParticleSet<2>& set, Name name) {
    set.add(name, 0.0);
};
static_assert(readableBy<sph::ScalarField> && addableBy<sph::ScalarField>);
static_assert(!readableBy<const char*> && !addableBy<const char*> && !readableBy<std::string>);
static_assert(std::is_same_v<decltype(std::declval<ParticleSet<2>&>()[fields::velocity]), std::vector<Vec<2>>&>);
static_assert(std::is_same_v<decltype(std::declval<ParticleSet<3>&>()[fields::density]), std::vector<double>&>);
static_assert(std::is_same_v<decltype(std::declval<const ParticleSet<2>&>()[fields::patch]), const std::vector<int>&>);

TEST(ParticleSet, FieldsFollowTheParticlesAndTheirOrder) {
    ParticleSet<2> set("fluid");
    set.resize(3);
    auto& density = set.add(fields::density, 1000.0);
    auto& velocity = set.add(fields::velocity, Vec<2>(1.0, 2.0));
    set.add(fields::patch, 7);
    EXPECT_EQ(density, std::vector<double>(3, 1000.0));
    EXPECT_EQ(velocity[2], Vec<2>(1.0, 2.0));
    density = {1.0, 2.0, 3.0};
    set.position = {Vec<2>(0.0, 0.0), Vec<2>(1.0, 0.0), Vec<2>(2.0, 0.0)};
    set.permute({2, 0, 1});
    EXPECT_EQ(set[fields::density], (std::vector<double>{3.0, 1.0, 2.0}));
    EXPECT_EQ(set.position[0], Vec<2>(2.0, 0.0));
    set.resize(5);
    EXPECT_EQ(set[fields::patch].size(), 5u);
    EXPECT_EQ(set[fields::velocity][4], Vec<2>::Zero());
}

TEST(ParticleSet, HalosFollowTheOwnedParticlesAndASelectionDropsThem) {
    ParticleSet<2> set("fluid");
    set.resize(3);
    auto& density = set.add(fields::density, 1.0);
    density = {1.0, 2.0, 3.0};
    set.globalId = {10, 11, 12};
    set.resizeHalos(2);
    EXPECT_EQ(set.ownedCount(), 3u);
    EXPECT_EQ(set.haloCount(), 2u);
    EXPECT_EQ(set[fields::density].size(), 5u);
    EXPECT_EQ(set[fields::density][2], 3.0);
    set.keep({2, 0});
    EXPECT_EQ(set.ownedCount(), 2u);
    EXPECT_EQ(set.haloCount(), 0u);
    EXPECT_EQ(set.globalId, (std::vector<std::int64_t>{12, 10}));
    EXPECT_EQ(set[fields::density], (std::vector<double>{3.0, 1.0}));
    EXPECT_THROW(set.permute({0}), std::logic_error);  // a permutation lists every particle
}

TEST(ParticleSet, AddingAFieldTwiceKeepsItsValuesAndWritesItIfEitherAsks) {
    ParticleSet<2> set("walls");
    set.resize(2);
    set.add(fields::pressure, 5.0, false);
    EXPECT_FALSE(set.scalars().at("pressure").written);
    EXPECT_EQ(set.add(fields::pressure, 9.0, true), std::vector<double>(2, 5.0));
    EXPECT_TRUE(set.scalars().at("pressure").written);
    set.add(fields::pressure, 0.0, false);
    EXPECT_TRUE(set.scalars().at("pressure").written);
}

TEST(ParticleSet, AnOptionalFieldIsNullWhereTheCaseLacksIt) {
    ParticleSet<3> set("walls");
    set.resize(4);
    EXPECT_FALSE(set.has(fields::acceleration));
    EXPECT_EQ(set.optionalData(fields::acceleration), nullptr);
    auto& acceleration = set.add(fields::acceleration, Vec<3>::Zero(), false);
    EXPECT_TRUE(set.has(fields::acceleration));
    EXPECT_EQ(set.optionalData(fields::acceleration), acceleration.data());
    // A scalar of the same name is another field.
    EXPECT_FALSE(set.has(sph::ScalarField{"acceleration"}));
}

TEST(ParticleSet, AFieldThatMustExistNamesTheSetAndTheField) {
    ParticleSet<2> set("fluid");
    try {
        set[fields::densityRate];
        FAIL() << "no error";
    } catch (const std::logic_error& e) {
        EXPECT_STREQ(e.what(), "particle set 'fluid' has no field 'densityRate'");
    }
}

// Library fields are found by slot; a key made at run time from a library name finds the same
// field, and a user's field (no slot) is found by name.
static_assert(fields::velocity.slot == 0 && fields::freeSurfaceLambda.slot == 22);
static_assert(sph::ScalarField{"myTracer"}.slot == -1);

TEST(ParticleSet, AKeyMadeFromANameFindsTheLibraryFieldOfThatName) {
    ParticleSet<2> set("fluid");
    set.resize(2);
    auto& read = set.add(sph::ScalarField{"density"}, 998.0);  // as the state-file reader does
    EXPECT_EQ(&set[fields::density], &read);
    set.add(sph::ScalarField{"myTracer"}, 0.5);
    EXPECT_EQ(set[sph::ScalarField{"myTracer"}], std::vector<double>(2, 0.5));
    EXPECT_FALSE(set.has(sph::ScalarField{"otherTracer"}));
}

TEST(ParticleSet, ACopyOwnsItsFieldsAndAMoveKeepsThem) {
    ParticleSet<2> original("fluid");
    original.resize(2);
    original.add(fields::density, 1000.0);
    ParticleSet<2> copy = original;
    copy[fields::density][0] = 1.0;
    EXPECT_EQ(original[fields::density][0], 1000.0);
    copy.add(fields::pressure, 3.0);
    EXPECT_FALSE(original.has(fields::pressure));

    ParticleSet<2> assigned("walls");
    assigned = copy;
    assigned[fields::pressure][1] = 4.0;
    EXPECT_EQ(copy[fields::pressure][1], 3.0);

    const double* data = copy[fields::density].data();
    ParticleSet<2> moved = std::move(copy);
    EXPECT_EQ(moved[fields::density].data(), data);
    EXPECT_EQ(moved[fields::pressure], std::vector<double>(2, 3.0));
    EXPECT_FALSE(copy.has(fields::density));  // NOLINT(bugprone-use-after-move): a moved-from set is empty, not dangling
    assigned = std::move(moved);
    EXPECT_EQ(assigned[fields::density].data(), data);
}
