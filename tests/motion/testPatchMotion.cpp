#include "core/FatalError.hpp"
#include "motion/GaussianBulge.hpp"
#include "motion/MotionTable.hpp"
#include "motion/Oscillation.hpp"
#include "motion/Rotation.hpp"
#include "motion/SlidingSurface.hpp"
#include "boundaryModels/RepulsiveWall.hpp"
#include "physics/FluidSystem.hpp"
#include "support/CaseFixture.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

using namespace sph;

namespace {

Dictionary dictionary(const std::string& text) { return Dictionary::fromString(text, "motion"); }

// Velocity and acceleration agree with central differences of the position.
template <int D>
void expectConsistentKinematics(const PatchMotion<D>& motion, const Vec<D>& x0, const Vec<D>& n0, double t) {
    const double e = 1e-5;
    const auto before = motion.at(x0, n0, t - e), now = motion.at(x0, n0, t), after = motion.at(x0, n0, t + e);
    EXPECT_LT((now.velocity - (after.position - before.position) / (2 * e)).norm(), 1e-6 * (1 + now.velocity.norm()));
    EXPECT_LT((now.acceleration - (after.velocity - before.velocity) / (2 * e)).norm(), 1e-5 * (1 + now.acceleration.norm()));
}

}  // namespace

TEST(PatchMotion, OscillationIsASinusoid) {
    const Oscillation<2> motion(dictionary("amplitude (0.1 0); frequency 0.5; phase 0;"));
    const auto k = motion.at(Vec<2>(1, 2), Vec<2>(0, 1), 0.5);  // quarter period
    EXPECT_NEAR((k.position - Vec<2>(1.1, 2)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(k.velocity.norm(), 0.0, 1e-14);
    EXPECT_NEAR(k.acceleration.x(), -0.1 * std::numbers::pi * std::numbers::pi, 1e-12);
    expectConsistentKinematics<2>(motion, Vec<2>(1, 2), Vec<2>(0, 1), 0.3);
}

TEST(PatchMotion, OscillationWithAPhaseStartsWhereThePatchWasGenerated) {
    // Phase pi/2: the surge A cos(omega t) of a tank displaced by A at rest: x0 + A (cos - 1).
    const Oscillation<2> motion(dictionary("amplitude (0.032 0); frequency 0.5; phase 1.5707963267948966;"));
    const auto start = motion.at(Vec<2>(1, 2), Vec<2>(0, 1), 0.0), half = motion.at(Vec<2>(1, 2), Vec<2>(0, 1), 1.0);
    EXPECT_NEAR((start.position - Vec<2>(1, 2)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(start.velocity.norm(), 0.0, 1e-15);
    EXPECT_NEAR((half.position - Vec<2>(1 - 0.064, 2)).norm(), 0.0, 1e-15);
    expectConsistentKinematics<2>(motion, Vec<2>(1, 2), Vec<2>(0, 1), 0.3);
}

TEST(PatchMotion, OscillationRampsUpWithoutAJump) {
    const Oscillation<2> ramped(dictionary("amplitude (0.1 0); frequency 0.5; phase 0; rampTime 2;"));
    const Oscillation<2> plain(dictionary("amplitude (0.1 0); frequency 0.5; phase 0;"));
    const Vec<2> x0(1, 2), n0(0, 1);
    const auto start = ramped.at(x0, n0, 0.0);
    EXPECT_EQ(start.position, x0);
    EXPECT_EQ(start.velocity.norm(), 0.0);
    EXPECT_EQ(start.acceleration.norm(), 0.0);  // the plain one starts at -A omega^2 sin(0) = 0 but with velocity A omega
    EXPECT_NEAR(plain.at(x0, n0, 0.0).velocity.x(), 0.1 * std::numbers::pi, 1e-15);
    // Half way: r(1/2) = 1/2.
    EXPECT_NEAR((ramped.at(x0, n0, 1.0).position - x0).x(), 0.5 * (plain.at(x0, n0, 1.0).position - x0).x(), 1e-15);
    for (double t : {0.3, 1.0, 1.7}) expectConsistentKinematics<2>(ramped, x0, n0, t);
    // At the ramp's end position, velocity and acceleration meet the plain motion's.
    const auto before = ramped.at(x0, n0, 2.0 - 1e-9), after = plain.at(x0, n0, 2.0 + 1e-9);
    EXPECT_NEAR((before.position - after.position).norm(), 0.0, 1e-9);
    EXPECT_NEAR((before.velocity - after.velocity).norm(), 0.0, 1e-8);
    EXPECT_NEAR((before.acceleration - after.acceleration).norm(), 0.0, 1e-7);
    EXPECT_EQ(ramped.at(x0, n0, 3.1).position, plain.at(x0, n0, 3.1).position);
}

TEST(PatchMotion, RotationTurnsPositionsAndNormals) {
    const Rotation motion(dictionary("centre (0 0); omega 0.5; amplitude 0.2; frequency 1;"));
    const double t = 1.0;  // theta = 0.5 + 0.2 sin(2 pi) = 0.5
    const auto k = motion.at(Vec<2>(1, 0), Vec<2>(0, 1), t);
    EXPECT_NEAR((k.position - Vec<2>(std::cos(0.5), std::sin(0.5))).norm(), 0.0, 1e-12);
    EXPECT_NEAR((motion.normalAt(Vec<2>(0, 1), t) - Vec<2>(-std::sin(0.5), std::cos(0.5))).norm(), 0.0, 1e-12);
    expectConsistentKinematics<2>(motion, Vec<2>(1, 0.3), Vec<2>(0, 1), 0.37);
}

TEST(PatchMotion, SlidingSurfaceStaysAndCarriesItsVelocity) {
    const SlidingSurface<2> lid(dictionary("velocity (1 0);"));
    const auto k = lid.at(Vec<2>(0.3, 1), Vec<2>(0, -1), 2.5);
    EXPECT_EQ(k.position, Vec<2>(0.3, 1));
    EXPECT_EQ(k.velocity, Vec<2>(1, 0));
    EXPECT_EQ(k.acceleration, Vec<2>::Zero());
    EXPECT_FALSE(lid.deforms());
    try {
        lid.at(Vec<2>(0, 0.5), Vec<2>(1, 0), 0.0);  // a side wall: U would push through it
        FAIL() << "a normal velocity was accepted";
    } catch (const FatalError& e) {
        EXPECT_NE(std::string(e.what()).find("slidingSurface velocity (1 0) is not tangential to the wall at (0 0.5), normal (1 0)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(PatchMotion, GaussianBulgeMovesAlongTheNormalAndDeforms) {
    const GaussianBulge<2> bulge(dictionary("centre (1 0); amplitude 0.1; width 0.2; period 2;"));
    EXPECT_TRUE(bulge.deforms());
    const auto top = bulge.at(Vec<2>(1, 0), Vec<2>(0, 1), 0.5);  // a quarter period: fully convex
    EXPECT_NEAR((top.position - Vec<2>(1, 0.1)).norm(), 0.0, 1e-14);
    const auto concave = bulge.at(Vec<2>(1, 0), Vec<2>(0, 1), 1.5);
    EXPECT_NEAR(concave.position.y(), -0.1, 1e-14);
    EXPECT_NEAR(bulge.at(Vec<2>(2, 0), Vec<2>(0, 1), 0.5).position.y(), 0.1 * std::exp(-25.0), 1e-15);
    expectConsistentKinematics<2>(bulge, Vec<2>(1.1, 0), Vec<2>(0, 1), 0.8);
}

TEST(PatchMotion, GaussianBulgeAreaStretchIsTheCrossProductOfTheMovedTangents) {
    // On the floor z = 0 (n0 = z), the moved surface's tangents by central differences:
    // dx/dx0 x dx/dy0 is the area vector per unit initial area (Nanson's formula).
    const GaussianBulge<3> bulge(dictionary("centre (0.5 0.3 0); amplitude 0.12; width 0.15; period 1.2;"));
    const Vec<3> n0(0, 0, 1);
    for (const Vec<3>& x0 : {Vec<3>(0.5, 0.3, 0), Vec<3>(0.6, 0.25, 0), Vec<3>(0.42, 0.41, 0)}) {
        for (double t : {0.3, 0.77, 0.9}) {
            const double e = 1e-6;
            const auto moved = [&](const Vec<3>& d) { return bulge.at(Vec<3>(x0 + d), n0, t).position; };
            const Vec<3> along = (moved(Vec<3>(e, 0, 0)) - moved(Vec<3>(-e, 0, 0))) / (2 * e);
            const Vec<3> across = (moved(Vec<3>(0, e, 0)) - moved(Vec<3>(0, -e, 0))) / (2 * e);
            EXPECT_LT((bulge.areaStretch(x0, n0, t) - along.cross(across)).norm(), 1e-8) << x0.transpose() << " t " << t;
        }
    }
    // At the top of the bulge the wall only moves: the same normal, the same area.
    EXPECT_LT((bulge.areaStretch(Vec<3>(0.5, 0.3, 0), n0, 0.3) - n0).norm(), 1e-15);
}

TEST(PatchMotion, DeformingPatchIn3DTakesNormalsAndAreasFromTheMotion) {
    // A 21 x 21 floor bulging into the fluid: the flanks' normals lean away from the centre, the
    // area grows, and an edge particle (no area) keeps none.
    ParticleSet<3> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = Vec<3>(0.5, 0.5, 0.5);
    fluid.add(fields::density, 1000.0);
    fluid.add(fields::mass, 1.0);
    fluid.add(fields::velocity, Vec<3>::Zero());
    ParticleSet<3> walls("walls");
    walls.resize(441);
    for (std::size_t k = 0; k < 441; ++k) walls.position[k] = Vec<3>(0.05 * double(k % 21), 0.05 * double(k / 21), 0.0);
    walls.add(fields::mass, 1.0);
    walls.add(fields::spacing, 0.05);
    auto& area = walls.add(fields::area, 0.0025);
    area[0] = 0.0;  // as boxWalls' edge particles
    walls.add(fields::normal, Vec<3>(0, 0, 1));
    walls.add(fields::patch, 0);
    walls.add(fields::layer, 0);
    std::vector<Patch<3>> patches(1);
    patches[0].name = "floor";
    patches[0].end = 441;
    patches[0].model = std::make_unique<RepulsiveWall<3>>(MonaghanKajtar2009{1e-9, 0.05, 0.0, 0.0});
    patches[0].motion = std::make_unique<GaussianBulge<3>>(dictionary("centre (0.5 0.5 0); amplitude 0.2; width 0.3; period 4;"));
    FluidModels<3> models{WendlandC2<3>(0.065), TaitEquationOfState(1000.0, 10.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    FluidSystem<3> system(std::move(models), std::move(fluid), std::move(walls), std::move(patches), Vec<3>(-1, -1, -1), Vec<3>(2, 2, 2),
                          Vec<3>::Zero(), 0.0);
    system.evaluateRates(1.0);  // full convex bulge
    const auto& n = system.walls[fields::normal];
    const auto& a = system.walls[fields::area];
    const std::size_t top = 10 * 21 + 10, leftFlank = 10 * 21 + 6, frontFlank = 6 * 21 + 10;
    EXPECT_NEAR(system.walls.position[top].z(), 0.2, 1e-14);
    EXPECT_LT((n[top] - Vec<3>(0, 0, 1)).norm(), 1e-12);
    EXPECT_NEAR(a[top], 0.0025, 1e-15);
    EXPECT_LT(n[leftFlank].x(), -0.3);
    EXPECT_NEAR(n[leftFlank].y(), 0.0, 1e-12);
    EXPECT_LT(n[frontFlank].y(), -0.3);
    EXPECT_NEAR(n[leftFlank].norm(), 1.0, 1e-14);
    EXPECT_NEAR(a[leftFlank], 0.0025 / n[leftFlank].z(), 1e-12);  // a graph z(x, y): dA = dx dy / n_z
    EXPECT_GT(system.walls[fields::spacing][leftFlank], 0.05);
    EXPECT_EQ(a[0], 0.0);
}

TEST(PatchMotion, TableInterpolatesAndMustCoverTheRun) {
    const auto dir = test::freshDirectory();
    test::writeFile(dir / "motion.csv", "# piston\nt,dx,dy\n0, 0, 0\n1, 0.1, 0\n2, 0.3, 0\n");
    const MotionTable<2> table(dictionary("file \"motion.csv\";"), dir.string());
    const auto k = table.at(Vec<2>(0, 0), Vec<2>(1, 0), 1.5);
    EXPECT_NEAR(k.position.x(), 0.2, 1e-14);
    EXPECT_NEAR(k.velocity.x(), 0.2, 1e-14);
    EXPECT_NEAR(k.acceleration.x(), 0.1, 1e-12);  // slope 0.1 -> 0.2 between midpoints 0.5 and 1.5
    EXPECT_NO_THROW(table.checkCovers(0.0, 2.0));
    try {
        table.checkCovers(0.0, 3.0);
        FAIL() << "a table shorter than the run was accepted";
    } catch (const FatalError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "error: motion table '" + (dir / "motion.csv").string() + "' covers t from 0 to 2, but the run goes from 0 to 3");
    }
    test::writeFile(dir / "bad.csv", "0 0 0\n1 0.1\n");
    EXPECT_THROW(MotionTable<2>(dictionary("file \"bad.csv\";"), dir.string()), FatalError);
    test::writeFile(dir / "backwards.csv", "0 0 0\n1 0.1 0\n0.5 0.2 0\n");
    try {
        MotionTable<2>(dictionary("file \"backwards.csv\";"), dir.string());
        FAIL();
    } catch (const FatalError& e) {
        EXPECT_NE(std::string(e.what()).find("line 3: time 0.5 does not increase"), std::string::npos) << e.what();
    }
}

namespace {

// A straight wall of 41 particles on y = 0, stored in the given order of x / 0.05, under a
// gaussianBulge of 0.2 at x = 1, evaluated at its full convex bulge (t = 1).
std::unique_ptr<FluidSystem<2>> bulgedFloor(const std::vector<std::size_t>& order) {
    ParticleSet<2> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = Vec<2>(1.0, 0.5);
    fluid.add(fields::density, 1000.0);
    fluid.add(fields::mass, 1.0);
    fluid.add(fields::velocity, Vec<2>::Zero());
    ParticleSet<2> walls("walls");
    walls.resize(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) walls.position[k] = Vec<2>(0.05 * double(order[k]), 0.0);
    walls.add(fields::mass, 1.0);
    walls.add(fields::spacing, 0.05);
    walls.add(fields::area, 0.05);
    walls.add(fields::normal, Vec<2>(0, 1));
    walls.add(fields::patch, 0);
    walls.add(fields::layer, 0);
    std::vector<Patch<2>> patches(1);
    patches[0].name = "floor";
    patches[0].end = order.size();
    patches[0].model = std::make_unique<RepulsiveWall<2>>(MonaghanKajtar2009{1e-9, 0.05, 0.0, 0.0});
    patches[0].motion = std::make_unique<GaussianBulge<2>>(dictionary("centre (1 0); amplitude 0.2; width 0.3; period 4;"));
    FluidModels<2> models{WendlandC2<2>(0.065), TaitEquationOfState(1000.0, 10.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    auto system = std::make_unique<FluidSystem<2>>(std::move(models), std::move(fluid), std::move(walls), std::move(patches), Vec<2>(-1, -1),
                                                   Vec<2>(3, 2), Vec<2>::Zero(), 0.0);
    system->evaluateRates(1.0);
    return system;
}

std::vector<std::size_t> alongTheWall() {
    std::vector<std::size_t> order(41);
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    return order;
}

}  // namespace

TEST(PatchMotion, DeformingPatchRecomputesNormalsAndSpacings) {
    // Stored along the wall (as polyline generates it): the chords of the moved neighbours.
    // The normals tilt away from the bulge's centre on its flanks and stay vertical at its top.
    const auto system = bulgedFloor(alongTheWall());
    const auto& n = system->walls[fields::normal];
    EXPECT_NEAR(system->walls.position[20].y(), 0.2, 1e-14);
    EXPECT_NEAR(n[20].x(), 0.0, 1e-12);
    EXPECT_LT(n[16].x(), -0.3);  // left flank leans left
    EXPECT_GT(n[24].x(), 0.3);
    EXPECT_GT(system->walls[fields::spacing][16], 0.05);  // stretched over the bulge
    EXPECT_NEAR(system->walls[fields::velocity][20].norm(), 0.0, 1e-12);
}

TEST(PatchMotion, DeformingPatchOutOfOrderTakesNormalsFromTheMotion) {
    // The same wall stored out of order (as boxWalls stores a lattice): no chords between
    // storage neighbours (a 2D boxWalls floor blew up at step 4 with them), the motion's normals
    // and areas instead, which agree with the ordered wall's chords to their accuracy.
    std::vector<std::size_t> shuffled;
    for (std::size_t k = 0; k < 41; k += 2) shuffled.push_back(k);
    for (std::size_t k = 1; k < 41; k += 2) shuffled.push_back(k);
    const auto chords = bulgedFloor(alongTheWall()), motion = bulgedFloor(shuffled);
    const auto& bulge = dynamic_cast<const GaussianBulge<2>&>(*motion->patches[0].motion);
    for (std::size_t k = 1; k + 1 < 41; ++k) {
        const std::size_t at = std::find(shuffled.begin(), shuffled.end(), k) - shuffled.begin();
        const Vec<2> exact = bulge.areaStretch(Vec<2>(0.05 * double(k), 0.0), Vec<2>(0, 1), 1.0);
        EXPECT_LT((motion->walls[fields::normal][at] - exact.normalized()).norm(), 1e-14) << k;
        EXPECT_NEAR(motion->walls[fields::area][at], 0.05 * exact.norm(), 1e-14) << k;
        EXPECT_LT((motion->walls[fields::normal][at] - chords->walls[fields::normal][k]).norm(), 0.03) << k;
        EXPECT_NEAR(motion->walls[fields::area][at], chords->walls[fields::area][k], 0.003) << k;
    }
}
