#include "core/FatalError.hpp"
#include "io/ParticleFile.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

TEST(ParticleFile, RoundTripIsBitExact) {
    const auto dir = sph::test::freshDirectory();
    sph::ParticleSet<2> set("fluid");
    set.resize(3);
    auto& rho = set.add(sph::fields::density, 0.0);
    auto& v = set.add(sph::fields::velocity, sph::Vec<2>::Zero());
    auto& patch = set.add(sph::fields::patch, 0);
    set.add(sph::ScalarField{"scratch"}, 1.0, false);
    for (std::size_t i = 0; i < 3; ++i) {
        set.position[i] = {0.1 * i + 1.0 / 3.0, -std::sqrt(2.0) * i};
        set.globalId[i] = static_cast<std::int64_t>(10 + i);
        rho[i] = 1000.0 + std::exp(-static_cast<double>(i));
        v[i] = {1e-17 * i, std::acos(-1.0)};
        patch[i] = static_cast<int>(i % 2);
    }
    sph::StateHeader header;
    header.dimension = 2;
    header.time = 0.125;
    header.step = 17;
    header.spacing = 0.01;
    header.domainMin = {-1, -2};
    header.domainMax = {3, 4};
    header.patchNames = {"left", "right"};
    header.patchLayers = {1, 4};
    sph::writeParticleFile(dir / "state.vtu", set, header);

    sph::StateHeader read;
    const auto back = sph::readParticleFile<2>(dir / "state.vtu", "fluid", read);
    EXPECT_EQ(read.time, 0.125);
    EXPECT_EQ(read.step, 17);
    EXPECT_EQ(read.spacing, 0.01);
    EXPECT_EQ(read.domainMax, header.domainMax);
    EXPECT_EQ(read.patchNames, header.patchNames);
    EXPECT_EQ(read.patchLayers, header.patchLayers);
    ASSERT_EQ(back.size(), 3u);
    EXPECT_FALSE(back.has(sph::ScalarField{"scratch"}));  // not written
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(back.position[i], set.position[i]);
        EXPECT_EQ(back.globalId[i], set.globalId[i]);
        EXPECT_EQ(back[sph::fields::density][i], rho[i]);
        EXPECT_EQ(back[sph::fields::velocity][i], v[i]);
        EXPECT_EQ(back[sph::fields::patch][i], patch[i]);
    }
    // Written through a temporary name: nothing else is left in the directory.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

TEST(ParticleFile, WritesTheParticlesAtTheGivenPlacesInTheirOrder) {
    // A decomposed run's owned particles among its halo copies: places 3 and 1 of five.
    const auto dir = sph::test::freshDirectory();
    sph::ParticleSet<3> set("fluid");
    set.resize(5);
    auto& rho = set.add(sph::fields::density, 0.0);
    auto& v = set.add(sph::fields::velocity, sph::Vec<3>::Zero());
    auto& patch = set.add(sph::fields::patch, 0);
    for (std::size_t i = 0; i < 5; ++i) {
        set.position[i] = sph::Vec<3>(0.1 * i, 1.0 / (1.0 + i), -1.0 * i);
        set.globalId[i] = static_cast<std::int64_t>(20 + i);
        rho[i] = 1000.0 + i;
        v[i] = sph::Vec<3>(i, 2.0 * i, 3.0 * i);
        patch[i] = static_cast<int>(7 * i);
    }
    sph::StateHeader header;
    header.dimension = 3;
    header.domainMin = {-10, -10, -10};
    header.domainMax = {10, 10, 10};
    const std::vector<std::uint32_t> places{3, 1};
    sph::writeParticleFile(dir / "piece.vtu", set, header, places);
    sph::StateHeader read;
    const auto back = sph::readParticleFile<3>(dir / "piece.vtu", "fluid", read);
    ASSERT_EQ(back.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        const std::size_t i = places[k];
        EXPECT_EQ(back.position[k], set.position[i]);
        EXPECT_EQ(back.globalId[k], set.globalId[i]);
        EXPECT_EQ(back[sph::fields::density][k], rho[i]);
        EXPECT_EQ(back[sph::fields::velocity][k], v[i]);
        EXPECT_EQ(back[sph::fields::patch][k], patch[i]);
    }
    // A rank that owns none of the particles it holds writes an empty piece.
    sph::writeParticleFile(dir / "empty.vtu", set, header, std::span<const std::uint32_t>());
    EXPECT_EQ(sph::readParticleFile<3>(dir / "empty.vtu", "fluid", read).size(), 0u);
}

TEST(ParticleFile, MissingAndCorruptFilesAreClearErrors) {
    const auto dir = sph::test::freshDirectory();
    sph::StateHeader header;
    try {
        sph::readParticleFile<2>(dir / "none.vtu", "fluid", header);
        FAIL();
    } catch (const sph::FatalError& e) {
        EXPECT_EQ(std::string(e.what()), "error: particle file '" + (dir / "none.vtu").string() + "' does not exist");
    }
    sph::test::writeFile(dir / "bad.vtu", "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\"><Unstr");
    try {
        sph::readParticleFile<2>(dir / "bad.vtu", "fluid", header);
        FAIL();
    } catch (const sph::FatalError& e) {
        EXPECT_NE(std::string(e.what()).find("error: particle file '" + (dir / "bad.vtu").string() + "': has no <AppendedData> section"),
                  std::string::npos)
            << e.what();
    }
}
