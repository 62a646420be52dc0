// Fluid region generation: boxes of any extent, closed surfaces, fluid beside a one-layer wall.
#include "generation/FluidRegions.hpp"

#include "generation/CubeSurface.hpp"
#include "generation/ParticleGenerator.hpp"
#include "io/ParticleFile.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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

TEST(FluidRegions, VelocityIsAVectorOrAnAnalyticField) {
    const GenerationDomain<2> domain{Vec<2>(0, 0), Vec<2>(1, 1), ""};
    const FluidRegionParticles<2> uniform =
        fillFluidRegion<2>(Dictionary::fromString("type box; min (0 0); max (0.4 0.2); velocity (3 -2);", "column"), 0.1, domain);
    EXPECT_EQ(uniform.velocity, Vec<2>(3, -2));
    EXPECT_FALSE(uniform.initialField);
    const FluidRegionParticles<2> vortex = fillFluidRegion<2>(
        Dictionary::fromString("type box; min (0 0); max (1 1); velocity { type taylorGreen; U 1; L 1; nu 0.01; }", "vortex"), 0.1, domain);
    ASSERT_TRUE(vortex.initialField);
    EXPECT_THROW(fillFluidRegion<2>(Dictionary::fromString("type box; min (0 0); max (1 1); velocity (3);", "column"), 0.1, domain), FatalError);
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
}

TEST(FluidRegions, SurfaceIn2DIsAClosedCurveOrASurfacesCrossSection) {
    // The unit square at dx = 0.1 in a domain [-0.5, 1.5]^2: the lattice points 0.05 ... 0.95,
    // 10^2, from an OBJ polyline and from the unit cube cut at z = 0.5 (its default cut z = 0
    // runs along its floor, so the test cuts through the middle).
    const GenerationDomain<2> domain{Vec<2>::Constant(-0.5), Vec<2>::Constant(1.5), ""};
    const std::vector<Vec<2>> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::filesystem::path curve = writeCurveObj("square.obj", square);
    EXPECT_EQ(
        fillFluidRegion<2>(Dictionary::fromString(fmt::format("type surface; file \"{}\";", curve.string()), "water"), 0.1, domain).positions.size(),
        100u);
    const std::filesystem::path cube = writeCubeObj("slicedCube.obj");
    const auto sliced =
        fillFluidRegion<2>(Dictionary::fromString(fmt::format("type surface; file \"{}\"; slice 0.5;", cube.string()), "water"), 0.1, domain);
    ASSERT_EQ(sliced.positions.size(), 100u);
    for (const Vec<2>& x : sliced.positions) EXPECT_TRUE(x.minCoeff() > 0.0 && x.maxCoeff() < 1.0) << x.transpose();
    // Two nested loops: the ring between them (even-odd), 10^2 - 4^2 with the inner square 0.3 ... 0.7.
    std::ofstream(curve.parent_path() / "ring.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.3 0.3 0\nv 0.7 0.3 0\nv 0.7 0.7 0\nv 0.3 0.7 0\n"
                                                       "l 1 2 3 4 1\nl 5 6 7 8 5\n";
    EXPECT_EQ(
        fillFluidRegion<2>(Dictionary::fromString(fmt::format("type surface; file \"{}\";", (curve.parent_path() / "ring.obj").string()), "water"),
                           0.1, domain)
            .positions.size(),
        84u);
    const auto failure = [&](const std::string& text) {
        try {
            fillFluidRegion<2>(Dictionary::fromString(text, "water"), 0.1, domain);
        } catch (const FatalError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    const std::filesystem::path open = writeCurveObj("openSquare.obj", square, true);
    EXPECT_NE(failure(fmt::format("type surface; file \"{}\";", open.string())).find("1 of its 1 curves do not close"), std::string::npos)
        << failure(fmt::format("type surface; file \"{}\";", open.string()));
    EXPECT_NE(failure(fmt::format("type surface; file \"{}\"; slice 2;", cube.string())).find("its surface does not cross the plane z = 2"),
              std::string::npos);
    EXPECT_NE(failure("type surface; file \"tank.dxf\";").find("unknown extension '.dxf'; valid: .obj (polylines, or a surface to slice), .stl"),
              std::string::npos);
}

TEST(FluidRegions, FluidInFrontOfAOneLayerWallIsMovedOutToHalfASpacingNotDropped) {
    // ellipticalTank2D: the lattice inside an ellipse 2 x 1 with one layer of wall particles on
    // it. Every lattice point inside is kept (counted here apart), none closer than dx/2 to a
    // wall particle; with three layers from the wall back the points near it are dropped instead.
    const auto dir = sph::test::copyCase("ellipticalTank2D");
    const double dx = 0.05;
    std::size_t inside = 0;
    for (int i = 0; i < 100; ++i)
        for (int j = 0; j < 60; ++j) {
            const double x = -2.5 + (i + 0.5) * dx, y = -1.5 + (j + 0.5) * dx;
            if (std::pow(x / 2.0, 2) + y * y < 1.0) ++inside;
        }
    const GenerationSummary oneLayer = generateParticles(dir, true);
    EXPECT_EQ(oneLayer.fluidParticles, inside);
    EXPECT_EQ(oneLayer.droppedFluidParticles, 0u);
    StateHeader header;
    const ParticleSet<2> fluid = readParticleFile<2>(dir / "0/fluid.vtu", "fluid", header);
    const ParticleSet<2> walls = readParticleFile<2>(dir / "0/walls.vtu", "walls", header);
    double closest = 1.0;
    for (std::size_t i = 0; i < fluid.size(); ++i)
        for (std::size_t j = 0; j < walls.size(); ++j) closest = std::min(closest, (fluid.position[i] - walls.position[j]).norm());
    EXPECT_GE(closest, 0.5 * dx * (1.0 - 1e-9));
    EXPECT_LT(closest, 0.5 * dx * 1.001);  // some were moved there

    sph::test::replaceInFile(dir / "system/generateParticlesDict", "layers 1; firstLayerOffset 0;", "layers 3; firstLayerOffset 0;");
    const GenerationSummary layered = generateParticles(dir, true);
    EXPECT_GT(layered.droppedFluidParticles, 0u);
    EXPECT_EQ(layered.fluidParticles + layered.droppedFluidParticles, inside);
}

TEST(FluidRegions, FluidBetweenTheParticlesOfACurvedOneLayerWallIsMovedOutToo) {
    // cylinderArray2D: the lattice around a cylinder of radius 0.0252313 with one layer of wall
    // particles on it. A lattice point between two wall particles can be further than dx/2 from
    // both and yet 0.13 dx from the surface; it too is moved out, to dx/2 in front of the
    // element it faces (the chord between particles sits inside the circle by 0.005 dx).
    const auto dir = sph::test::copyCase("cylinderArray2D");
    const double dx = 0.002, radius = 0.0252313;
    const GenerationSummary summary = generateParticles(dir, true);
    EXPECT_EQ(summary.fluidParticles, 2000u);  // every lattice point outside the circle
    StateHeader header;
    const ParticleSet<2> fluid = readParticleFile<2>(dir / "0/fluid.vtu", "fluid", header);
    double closest = 1.0;
    for (const Vec<2>& x : fluid.position) closest = std::min(closest, (x - Vec<2>(0.05, 0.05)).norm() - radius);
    EXPECT_GT(closest, 0.49 * dx);
    EXPECT_LT(closest, 0.5 * dx * 1.001);  // some were moved there
}
