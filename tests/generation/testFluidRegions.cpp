// Fluid region generation: boxes of any extent.
#include "generation/FluidRegions.hpp"

#include "generation/CubeSurface.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>

using namespace sph;

TEST(FluidRegions, BoxOfAWholeNumberOfSpacingsIsThePlainLattice) {
    const Dictionary region = Dictionary::fromString("type box; min (0 0); max (0.4 0.2);", "column");
    const FluidRegionParticles<2> filled = fillFluidRegion<2>(region, 0.1, {Vec<2>(0, 0), Vec<2>(1, 1), ""});
    ASSERT_EQ(filled.positions.size(), 8u);
    for (const Vec<2>& x : filled.positions) {
        const double i = x.x() / 0.1 - 0.5, j = x.y() / 0.1 - 0.5;
        EXPECT_NEAR(i, std::round(i), 1e-12);
        EXPECT_NEAR(j, std::round(j), 1e-12);
    }
    EXPECT_TRUE(filled.notes.empty());
}

TEST(FluidRegions, BoxOfAnyExtentEndsHalfASpacingInsideIt) {
    // 0.47 x 0.2 at dx = 0.1: round(4.7) = 5 columns at 0.05, 0.15, 0.25, 0.35 and 0.47 - 0.05 = 0.42.
    const Dictionary region = Dictionary::fromString("type box; min (0 0); max (0.47 0.2);", "column");
    const FluidRegionParticles<2> filled = fillFluidRegion<2>(region, 0.1, {Vec<2>(0, 0), Vec<2>(1, 1), ""});
    ASSERT_EQ(filled.positions.size(), 10u);
    std::vector<double> columns;
    for (const Vec<2>& x : filled.positions)
        if (x.y() < 0.1) columns.push_back(x.x());
    std::sort(columns.begin(), columns.end());
    const std::vector<double> expected{0.05, 0.15, 0.25, 0.35, 0.42};
    ASSERT_EQ(columns.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(columns[k], expected[k], 1e-12);
    ASSERT_EQ(filled.notes.size(), 1u);
    EXPECT_EQ(filled.notes[0], "the x extent 0.47 is 4.7 dx: the last spacing is 0.7 dx");
}

TEST(FluidRegions, BoxOneParticleAcrossSitsInItsMiddle) {
    const Dictionary region = Dictionary::fromString("type box; min (0 0); max (0.13 0.2);", "sliver");
    const FluidRegionParticles<2> filled = fillFluidRegion<2>(region, 0.1, {Vec<2>(0, 0), Vec<2>(1, 1), ""});
    ASSERT_EQ(filled.positions.size(), 2u);
    EXPECT_NEAR(filled.positions[0].x(), 0.065, 1e-12);
}

TEST(FluidRegions, SurfaceKeepsTheDomainLatticeInsideAClosedSurface) {
    // The unit cube in a domain [-0.5, 1.5]^3 at dx = 0.1: the lattice points 0.05 ... 0.95, 10^3.
    const std::filesystem::path file = writeCubeObj("fluidCube.obj");
    const Dictionary region = Dictionary::fromString(fmt::format("type surface; file \"{}\";", file.string()), "water");
    const FluidRegionParticles<3> filled = fillFluidRegion<3>(region, 0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""});
    ASSERT_EQ(filled.positions.size(), 1000u);
    for (const Vec<3>& x : filled.positions) {
        EXPECT_GT(x.minCoeff(), 0.0);
        EXPECT_LT(x.maxCoeff(), 1.0);
    }
    // scale 0.5: the cube [0, 0.5]^3 holds 5^3.
    const Dictionary half = Dictionary::fromString(fmt::format("type surface; file \"{}\"; scale 0.5;", file.string()), "water");
    EXPECT_EQ(fillFluidRegion<3>(half, 0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""}).positions.size(), 125u);
}

TEST(FluidRegions, SurfaceThatIsOpenOrMissingIsRefusedNamingTheFile) {
    const auto failure = [](const std::string& text) {
        try {
            fillFluidRegion<3>(Dictionary::fromString(text, "water"), 0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""});
        } catch (const FatalError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    const std::filesystem::path open = writeCubeObj("openCube.obj", true);
    EXPECT_NE(failure(fmt::format("type surface; file \"{}\";", open.string())).find("keyword 'file'"), std::string::npos);
    EXPECT_NE(failure(fmt::format("type surface; file \"{}\";", open.string())).find("is not closed: 4 of its 17 edges"), std::string::npos)
        << failure(fmt::format("type surface; file \"{}\";", open.string()));
    EXPECT_NE(failure("type surface; file \"nowhere.stl\";").find("surface file 'nowhere.stl' does not exist"), std::string::npos);
    EXPECT_NE(failure("type surface; file \"tank.step\";").find("unknown extension '.step'; valid: .stl (ASCII or binary), .obj"), std::string::npos);
    EXPECT_THROW(fillFluidRegion<2>(Dictionary::fromString("type surface; file \"a.stl\";", "water"), 0.1, {Vec<2>::Zero(), Vec<2>::Ones(), ""}),
                 FatalError);
}
