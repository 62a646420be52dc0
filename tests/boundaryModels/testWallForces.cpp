// Wall-force boundary models: the repulsion laws against hand-computed values, and the
// deficiency correction against what it must achieve exactly (1D: the sampled particle's
// deficiency vanishes; a straight 2D wall: the first row's normal acceleration vanishes).
#include "boundaryModels/DeficiencyCorrection.hpp"
#include "boundaryModels/DeficiencyWeightingBoundaryIntegral.hpp"
#include "boundaryModels/DeficiencyWeightingJones2010.hpp"
#include "boundaryModels/RepulsiveWall.hpp"
#include "core/FatalError.hpp"
#include "physics/FluidSystem.hpp"

#include <gtest/gtest.h>

using namespace sph;

namespace {

constexpr double rho0 = 1000.0, dx = 0.05;

ModelContext contextFor(double h) { return {dx, h, 10.0, rho0, 0.0, rho0 * 100.0, 1.0}; }

template <int D>
ParticleSet<D> wallSet(const std::vector<Vec<D>>& positions, const Vec<D>& normal, double spacing) {
    ParticleSet<D> walls("walls");
    walls.resize(positions.size());
    walls.position = positions;
    walls.addScalar("mass", rho0 * std::pow(dx, D));
    walls.addScalar("spacing", spacing);
    walls.addVector("normal", normal);
    walls.addInteger("patch", 0);
    return walls;
}

template <int D>
ParticleSet<D> fluidSet(const std::vector<Vec<D>>& positions) {
    ParticleSet<D> fluid("fluid");
    fluid.resize(positions.size());
    fluid.position = positions;
    for (std::size_t i = 0; i < positions.size(); ++i) fluid.globalId[i] = static_cast<std::int64_t>(i);
    fluid.addScalar("density", rho0);
    fluid.addScalar("mass", rho0 * std::pow(dx, D));
    fluid.addVector("velocity", Vec<D>::Zero());
    return fluid;
}

// Uniform pressure 1 (linear EOS with background pressure 1), no gravity, cubic spline.
template <int D>
std::unique_ptr<FluidSystem<D>> system(ParticleSet<D> fluid, ParticleSet<D> walls, std::unique_ptr<BoundaryModel<D>> model, double h, const Vec<D>& lo,
                      const Vec<D>& hi) {
    std::vector<Patch<D>> patches(1);
    patches[0].name = "wall";
    patches[0].begin = 0;
    patches[0].end = walls.size();
    patches[0].model = std::move(model);
    FluidModels<D> models{CubicSplineMonaghanLattanzio1985<D>(h), LinearEquationOfState(rho0, 10.0, 1.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    return std::make_unique<FluidSystem<D>>(std::move(models), std::move(fluid), std::move(walls), std::move(patches), lo, hi, Vec<D>::Zero(), 0.0);
}

Dictionary dictionary(const std::string& text) { return Dictionary::fromString(text, "boundaryProperties"); }

// A wall of 200 particles along y = 0 under a 200 x 20 block at uniform pressure, evaluated once.
template <class Weighting>
std::unique_ptr<FluidSystem<2>> straightWall(const std::string& type) {
    const double h = 1.3 * dx;
    std::vector<Vec<2>> fluid, walls;
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 200; ++i) fluid.push_back(Vec<2>((i + 0.5) * dx, (j + 0.5) * dx));
    for (int i = 0; i < 200; ++i) walls.push_back(Vec<2>((i + 0.5) * dx, 0.0));
    const auto dict = dictionary("type " + type + "; repulsion { type monaghanKajtar; K 1e-12; } sample { type nearest; size 2; }");
    auto s = system<2>(fluidSet<2>(fluid), wallSet<2>(walls, Vec<2>(0, 1), dx),
                       std::make_unique<DeficiencyCorrection<2, Weighting>>(dict, contextFor(h), type), h, Vec<2>(-1, -1), Vec<2>(11, 2));
    s->evaluateRates(0.0);
    return s;
}

}  // namespace

TEST(MonaghanKajtar2009, HandComputedForceOnOneParticle) {
    const double h = 1.3 * dx;
    const Vec<2> wall(0.0, 0.0), particle(0.01, 0.03);
    const double spacing = 0.025;  // beta = dx / s = 2
    auto owner = system<2>(fluidSet<2>({particle}), wallSet<2>({wall}, Vec<2>(0, 1), spacing),
                       std::make_unique<RepulsiveWall<2>>(readRepulsionLaw(dictionary("type monaghanKajtar; K 3;"), contextFor(h))), h,
                       Vec<2>(-1, -1), Vec<2>(1, 1));
    auto& s = *owner;
    s.evaluateRates(0.0);
    const CubicSplineMonaghanLattanzio1985<2> kernel(h);
    const Vec<2> r = particle - wall;
    const double expected = 3.0 / 2.0 * kernel.value(r.norm()) / kernel.value(0.0) * 1.0 / r.squaredNorm();  // 2 m/(m + m) = 1
    EXPECT_NEAR((s.fluid.vector("acceleration")[0] - expected * r).norm(), 0.0, 1e-12 * expected * r.norm());
}

TEST(MonaghanKajtar2009, ShiftedFormIsStrongerNearTheWallAndClipped) {
    const MonaghanKajtar2009 square{1.0, dx, 0.0, 0.0}, shifted{1.0, dx, 0.5 * dx, 0.1 * dx};
    const Vec<2> r(0.0, 0.6 * dx);
    EXPECT_NEAR(shifted.acceleration<2>(r, 0.6 * dx, 1.0, dx, 1.0, 1.0).y(), 1.0 / (0.6 * dx * 0.1 * dx) * 0.6 * dx, 1e-9);
    EXPECT_GT(shifted.acceleration<2>(r, 0.6 * dx, 1.0, dx, 1.0, 1.0).y(), square.acceleration<2>(r, 0.6 * dx, 1.0, dx, 1.0, 1.0).y());
    // Inside the shift the distance is clipped, not negative.
    EXPECT_GT(shifted.acceleration<2>(Vec<2>(0.0, 0.2 * dx), 0.2 * dx, 1.0, dx, 1.0, 1.0).y(), 0.0);
}

TEST(LennardJonesMonaghan1994, HandComputedAndZeroBeyondR0) {
    const LennardJonesMonaghan1994 lj{5.0, 0.05, 12, 4};
    const Vec<2> r(0.03, 0.0);
    const double ratio = 0.05 / 0.03;
    EXPECT_NEAR(lj.acceleration<2>(r, 0.03).x(), 5.0 * (std::pow(ratio, 12) - std::pow(ratio, 4)) / 0.03, 1e-9);
    EXPECT_EQ(lj.acceleration<2>(Vec<2>(0.06, 0.0), 0.06).x(), 0.0);
}

TEST(DeficiencyCorrection, OneDimensionCancelsTheSampledDeficiencyExactly) {
    // 1D fluid at uniform pressure to the right of a wall particle at x = 0 (Fig. 3 of the paper).
    const double h = 2.0 * dx;
    std::vector<Vec<1>> positions;
    for (int k = 0; k < 40; ++k) positions.push_back(Vec<1>((k + 0.5) * dx));
    for (const char* calibration : {"calibrated", "literal"}) {
        const auto dict = dictionary(std::string("type deficiencyCorrection; repulsion { type monaghanKajtar; K 1e-12; } sample { type nearest; size 1; } calibration ") +
                                     calibration + ";");
        auto owner = system<1>(fluidSet<1>(positions), wallSet<1>({Vec<1>(0.0)}, Vec<1>(1.0), dx),
                           std::make_unique<DeficiencyCorrection<1, DeficiencyWeightingJones2010>>(dict, contextFor(h), "deficiencyCorrection"), h,
                           Vec<1>(-1.0), Vec<1>(3.0));
        auto& s = *owner;
        s.evaluateRates(0.0);
        const auto& before = s.fluid.vector("uncorrectedAcceleration");
        const auto& correction = s.fluid.vector("boundaryCorrection");
        const double C = s.walls.scalar("correctionCoefficient")[0];
        EXPECT_LT(before[0].x(), 0.0) << "the deficiency pulls the fluid towards the wall";
        EXPECT_LT(C, 0.0);
        // C = a_s / W(r_s) for the nearest particle: its corrected acceleration is zero.
        const CubicSplineMonaghanLattanzio1985<1> kernel(h);
        EXPECT_NEAR(C, before[0].x() / kernel.value(0.5 * dx), 1e-15);
        EXPECT_NEAR(before[0].x() + correction[0].x(), 0.0, 1e-15);
        // Particles 1 and 2 keep a smaller residual than their deficiency. Particle 3 (3.5 dx from
        // the wall, support 4 dx) has no deficiency but still receives a small correction: the
        // correction reaches r_inf from the wall, the deficiency only r_inf - dx/2.
        EXPECT_LT(std::abs(before[3].x()), 1e-15);
        for (std::size_t k = 1; k < 3; ++k) EXPECT_LT(std::abs(before[k].x() + correction[k].x()), std::abs(before[k].x())) << calibration << " " << k;
    }
}

TEST(DeficiencyCorrection, StraightWallIn2DLeavesNoNormalAccelerationOnTheFirstRow) {
    // A wall of 200 particles along y = 0 under a 200 x 20 block; in the middle every C_j is
    // equal, and the calibrated reading cancels the sampled (first-row) deficiency.
    auto system = straightWall<DeficiencyWeightingJones2010>("deficiencyCorrection");
    auto& s = *system;
    const auto& before = s.fluid.vector("uncorrectedAcceleration");
    const auto& correction = s.fluid.vector("boundaryCorrection");
    const double deficiency = std::abs(before[100].y());
    ASSERT_GT(deficiency, 0.0);
    EXPECT_NEAR(before[100].y() + correction[100].y(), 0.0, 1e-12 * deficiency);  // first row, middle
    EXPECT_NEAR(correction[100].x(), 0.0, 1e-12 * deficiency);
    // The second row is corrected too, though not exactly (the kernel is not the deficiency's shape).
    EXPECT_LT(std::abs(before[300].y() + correction[300].y()), 0.5 * std::abs(before[300].y()));
}

TEST(DeficiencyCorrection, BoundaryIntegralWeightingAlsoCancelsOnAStraightWall) {
    auto system = straightWall<DeficiencyWeightingBoundaryIntegral>("deficiencyCorrectionBoundaryIntegral");
    auto& s = *system;
    const auto& before = s.fluid.vector("uncorrectedAcceleration");
    const auto& correction = s.fluid.vector("boundaryCorrection");
    EXPECT_NEAR(before[100].y() + correction[100].y(), 0.0, 1e-12 * std::abs(before[100].y()));
}

TEST(DeficiencyCorrection, NeedsARepulsionPartner) {
    try {
        DeficiencyCorrection<2, DeficiencyWeightingJones2010>(dictionary("type deficiencyCorrection;"), contextFor(0.065), "deficiencyCorrection");
        FAIL() << "accepted a correction without repulsion";
    } catch (const FatalError& e) {
        EXPECT_NE(std::string(e.what()).find("deficiencyCorrection needs a repulsion partner to stop penetration"), std::string::npos) << e.what();
    }
    try {
        readRepulsionLaw(dictionary("type hardWall;"), contextFor(0.065));
        FAIL();
    } catch (const FatalError& e) {
        EXPECT_STREQ(e.what(), "boundaryProperties:1:6: error: unknown repulsion 'hardWall'; valid repulsion names are:\n    lennardJones\n    monaghanKajtar");
    }
}

TEST(DeficiencyCorrection, WorksIn3DOnAParticleSurfaceWithNormals) {
    // A 3D floor: 30 x 30 wall particles at z = 0, a 30 x 30 x 8 block above; the weight uses
    // only distances and normals, so the first layer's sampled deficiency cancels in 3D too.
    const double h = 1.3 * dx;
    std::vector<Vec<3>> fluid, walls;
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 30; ++j)
            for (int i = 0; i < 30; ++i) fluid.push_back(Vec<3>((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx));
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 30; ++i) walls.push_back(Vec<3>((i + 0.5) * dx, (j + 0.5) * dx, 0.0));
    const auto dict = dictionary("type deficiencyCorrection; repulsion { type monaghanKajtar; K 1e-12; } sample { type nearest; size 1; }");
    auto owner = system<3>(fluidSet<3>(fluid), wallSet<3>(walls, Vec<3>(0, 0, 1), dx),
                       std::make_unique<DeficiencyCorrection<3, DeficiencyWeightingJones2010>>(dict, contextFor(h), "deficiencyCorrection"), h,
                       Vec<3>(-1, -1, -1), Vec<3>(2, 2, 1));
    auto& s = *owner;
    s.evaluateRates(0.0);
    const std::size_t middle = 15 * 30 + 15;  // first layer, centre of the floor
    const auto& before = s.fluid.vector("uncorrectedAcceleration");
    const auto& correction = s.fluid.vector("boundaryCorrection");
    ASSERT_LT(before[middle].z(), 0.0);
    EXPECT_NEAR(before[middle].z() + correction[middle].z(), 0.0, 1e-12 * std::abs(before[middle].z()));
    EXPECT_NEAR(correction[middle].x(), 0.0, 1e-12 * std::abs(before[middle].z()));
    EXPECT_NEAR(correction[middle].y(), 0.0, 1e-12 * std::abs(before[middle].z()));
}

TEST(DeficiencyWeighting, HandComputedWeights) {
    // A = 0.25/0.5, G = 1 (along the normal), D = 1 - 0.5/1: w = 0.25 + 1.5 * 0.5 = 1.
    EXPECT_DOUBLE_EQ(DeficiencyWeightingJones2010::weight<2>(0.5, Vec<2>(0, 1), Vec<2>(0, 1), 0.25, 1.0), 1.0);
    // Glancing at 90 degrees: G = 0, w = 0.25 + 0.5 * 0.5 = 0.5.
    EXPECT_DOUBLE_EQ(DeficiencyWeightingJones2010::weight<2>(0.5, Vec<2>(1, 0), Vec<2>(0, 1), 0.25, 1.0), 0.5);
    // The boundary-integral weight is the particle's area: s in 2D, s^2 in 3D.
    EXPECT_DOUBLE_EQ(DeficiencyWeightingBoundaryIntegral::weight<2>(0.5, Vec<2>(0, 1), Vec<2>(0, 1), 0.25, 1.0), 0.25);
    EXPECT_DOUBLE_EQ(DeficiencyWeightingBoundaryIntegral::weight<3>(0.5, Vec<3>(0, 0, 1), Vec<3>(0, 0, 1), 0.25, 1.0), 0.0625);
}
