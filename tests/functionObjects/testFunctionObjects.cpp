// Function objects on a lattice block with known fields: interpolation at probes, error norms
// against an analytic field and against a reference time series, gauge heights, and the
// errors a case can make in them (caught before the first step).
#include "analytic/TaylorGreen2D.hpp"
#include "boundaryModels/DummyParticlesAdami2012.hpp"
#include "boundaryModels/RepulsiveWall.hpp"
#include "functionObjects/ColumnHeight.hpp"
#include "functionObjects/FieldErrorNorm.hpp"
#include "functionObjects/FieldTotals.hpp"
#include "functionObjects/LineSample.hpp"
#include "functionObjects/Probes.hpp"
#include "functionObjects/ReferenceSeries.hpp"
#include "functionObjects/WallPressureSensors.hpp"
#include "functionObjects/WaveGauge.hpp"
#include "motion/Translation.hpp"
#include "physics/FluidSystem.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace sph;
using namespace sph::test;

constexpr double dx = 0.04;
constexpr int n = 25;  // a 1 x 1 block of fluid in the domain [-0.1, 1.1]^2

ParticleSet<2> blockFluid() {
    ParticleSet<2> fluid("fluid");
    fluid.resize(n * n);
    fluid.add(fields::density, 1000.0);
    fluid.add(fields::mass, 1000.0 * dx * dx);
    fluid.add(fields::velocity, Vec<2>::Zero());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t k = static_cast<std::size_t>(j * n + i);
            fluid.position[k] = {(i + 0.5) * dx, (j + 0.5) * dx};
            fluid.globalId[k] = static_cast<std::int64_t>(k);
        }
    return fluid;
}

// With `tankMotion`, one wall particle in a corner of the domain makes a patch "tank" that moves so.
std::unique_ptr<FluidSystem<2>> makeBlock(std::unique_ptr<PatchMotion<2>> tankMotion = nullptr) {
    ParticleSet<2> walls("walls");
    walls.add(fields::mass, 0.0);
    std::vector<Patch<2>> patches;
    if (tankMotion) {
        walls.resize(1);
        walls.position[0] = Vec<2>(1.09, 1.09);
        walls.add(fields::spacing, dx);
        walls.add(fields::normal, Vec<2>(0, 1));
        walls.add(fields::patch, 0);
        patches.resize(1);
        patches[0].name = "tank";
        patches[0].end = 1;
        patches[0].model = std::make_unique<RepulsiveWall<2>>(MonaghanKajtar2009{1e-9, dx, 0.0, 0.0});
        patches[0].motion = std::move(tankMotion);
    }
    FluidModels<2> models{WendlandC2<2>(1.3 * dx), LinearEquationOfState(1000.0, 10.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    auto system = std::make_unique<FluidSystem<2>>(std::move(models), blockFluid(), std::move(walls), std::move(patches), Vec<2>(-0.1, -0.1),
                                                   Vec<2>(1.1, 1.1), Vec<2>(0.0, -9.81), 0.0);
    system->evaluateRates(0.0);  // builds the cell list the interpolation searches
    return system;
}

// The block on a floor: one layer of wall particles on y = 0 from x = -0.08 to 1.08, a patch
// "floor" with `model` and, optionally, a motion; hydrostatic fluid pressure rho0 g (1 - y).
std::unique_ptr<FluidSystem<2>> makeBlockOnAFloor(std::unique_ptr<BoundaryModel<2>> model, std::unique_ptr<PatchMotion<2>> motion = nullptr) {
    ParticleSet<2> walls("walls");
    constexpr int count = 30;
    walls.resize(count);
    for (int k = 0; k < count; ++k) {
        walls.position[static_cast<std::size_t>(k)] = Vec<2>(-0.08 + k * dx, 0.0);
        walls.globalId[static_cast<std::size_t>(k)] = k;
    }
    walls.add(fields::mass, 1000.0 * dx * dx);
    walls.add(fields::spacing, dx);
    walls.add(fields::area, dx);
    walls.add(fields::normal, Vec<2>(0, 1));
    walls.add(fields::patch, 0);
    walls.add(fields::layer, 0);
    std::vector<Patch<2>> patches(1);
    patches[0].name = "floor";
    patches[0].end = count;
    patches[0].model = std::move(model);
    patches[0].motion = std::move(motion);
    FluidModels<2> models{WendlandC2<2>(1.3 * dx), LinearEquationOfState(1000.0, 10.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    auto system = std::make_unique<FluidSystem<2>>(std::move(models), blockFluid(), std::move(walls), std::move(patches), Vec<2>(-0.1, -0.1),
                                                   Vec<2>(1.1, 1.1), Vec<2>(0.0, -9.81), 0.0);
    system->evaluateRates(0.0);
    auto& p = system->fluid[fields::pressure];
    for (std::size_t i = 0; i < system->fluid.size(); ++i) p[i] = 1000.0 * 9.81 * (1.0 - system->fluid.position[i].y());
    return system;
}

std::unique_ptr<BoundaryModel<2>> dummyParticles() {
    return std::make_unique<DummyParticlesAdami2012<2>>(Dictionary::fromString("noSlip no;", "floor"), ModelContext{});
}

FunctionObjectContext<2> contextFor(const std::filesystem::path& dir, const FluidSystem<2>& system) {
    return {dir, dir / "postProcessing" / "object" / "0", 1000.0, system.view()};
}

// The header and first row of a function object's time series.
std::pair<std::string, std::string> headerAndFirstRow(const std::filesystem::path& file) {
    std::ifstream written(file);
    std::string header, row;
    std::getline(written, header);
    std::getline(written, row);
    return {header, row};
}

std::string errorOf(const std::function<void()>& construct) {
    try {
        construct();
    } catch (const FatalError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(Probes, InterpolateALinearFieldExactlyAtASymmetricPointAndReadZeroWhenDry) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    auto& p = system->fluid[fields::pressure];
    for (std::size_t i = 0; i < system->fluid.size(); ++i) p[i] = 100.0 + 50.0 * system->fluid.position[i].x() + 20.0 * system->fluid.position[i].y();
    const Dictionary dict = Dictionary::fromString("type probes; fields (p rho Ux); points ((0.5 0.5) (0.3 0.7) (1.09 1.09));", "probes");
    Probes<2> probes(dict, contextFor(dir, *system));
    const auto values = probes.sample(system->view(), 0.0);
    // A lattice point of the block: the kernel weights are symmetric, so a linear field is exact.
    EXPECT_NEAR(values[0][0], 100.0 + 25.0 + 10.0, 1e-9);
    EXPECT_NEAR(values[0][1], 100.0 + 15.0 + 14.0, 1e-9);
    EXPECT_NEAR(values[1][0], 1000.0, 1e-9);
    EXPECT_EQ(values[0][2], 0.0);  // 0.156 from the nearest particle, beyond the support 0.104
    probes.execute(system->view(), 0.5);
    const auto [header, row] = headerAndFirstRow(dir / "postProcessing/object/0/p.dat");
    EXPECT_EQ(header, "# time p(0.5 0.5) p(0.3 0.7) p(1.09 1.09)");
    EXPECT_EQ(row, "0.5 135 129 0");
}

// A probe on a patch that translates at 0.3 m/s reads the linear field where the patch has
// carried it; the same probe in the lab frame stays put.
TEST(Probes, OnAMovingPatchFollowIt) {
    const auto dir = freshDirectory();
    auto system = makeBlock(std::make_unique<Translation<2>>(Dictionary::fromString("velocity (0.3 0);", "motion")));
    auto& p = system->fluid[fields::pressure];
    for (std::size_t i = 0; i < system->fluid.size(); ++i) p[i] = 100.0 + 50.0 * system->fluid.position[i].x() + 20.0 * system->fluid.position[i].y();
    Probes<2> moving(Dictionary::fromString("type probes; fields (p); points ((0.2 0.5)); patch tank;", "probes"), contextFor(dir, *system));
    Probes<2> fixed(Dictionary::fromString("type probes; fields (p); points ((0.2 0.5));", "probes"), contextFor(dir, *system));
    EXPECT_NEAR(moving.sample(system->view(), 1.0)[0][0], 100.0 + 50.0 * 0.5 + 20.0 * 0.5, 1e-9);  // carried to x = 0.5
    EXPECT_NEAR(fixed.sample(system->view(), 1.0)[0][0], 100.0 + 50.0 * 0.2 + 20.0 * 0.5, 1e-9);
    EXPECT_NE(moving.describe().find("moving with patch tank"), std::string::npos);
    EXPECT_THROW(Probes<2>(Dictionary::fromString("type probes; fields (p); points ((0.2 0.5)); patch lid;", "probes"), contextFor(dir, *system)),
                 FatalError);
}

TEST(Probes, OutsideTheDomainOrAnUnknownFieldIsAnErrorBeforeTheRun) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    const Dictionary outside = Dictionary::fromString("type probes; fields (p); points ((0.5 0.5) (1.2 0.5));", "probes");
    EXPECT_NE(
        errorOf([&] { Probes<2>(outside, contextFor(dir, *system)); }).find("probe 1 at (1.2 0.5) lies outside the domain [(-0.1 -0.1), (1.1 1.1)]"),
        std::string::npos);
    const Dictionary unknown = Dictionary::fromString("type probes; fields (T); points ((0.5 0.5));", "probes");
    EXPECT_NE(errorOf([&] { Probes<2>(unknown, contextFor(dir, *system)); }).find("unknown field 'T'; valid fields in 2D are: p, rho, U, Ux, Uy"),
              std::string::npos);
}

TEST(ReferenceSeries, InterpolatesInTimeAndAccumulatesNormsOverTheOverlap) {
    const auto dir = freshDirectory();
    writeFile(dir / "ref.csv", "# a comment\nT,other,Z\n0,9,1\n1,9,3\n2,9,3\n");
    const Dictionary dict = Dictionary::fromString("file \"ref.csv\"; time T; columns (Z); timeScale 0.5; valueScale 2; scale 4;", "reference");
    ReferenceSeries reference(dict, dir, {"front"});
    // Times 0, 0.5, 1 s; values 2, 6, 6.
    EXPECT_DOUBLE_EQ(reference.at(0.25)->at(0), 4.0);
    EXPECT_DOUBLE_EQ(reference.at(0.75)->at(0), 6.0);
    EXPECT_FALSE(reference.at(1.5));
    reference.compare(0.25, {5.0});   // error +1
    reference.compare(0.75, {3.0});   // error -3
    reference.compare(2.0, {100.0});  // outside: not compared
    const auto errors = reference.errors();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].quantity, "front");
    EXPECT_DOUBLE_EQ(errors[0].norms.l1, 2.0 / 4.0);
    EXPECT_DOUBLE_EQ(errors[0].norms.l2, std::sqrt(5.0) / 4.0);
    EXPECT_DOUBLE_EQ(errors[0].norms.linf, 3.0 / 4.0);
    EXPECT_EQ(errors[0].normalisation, "scale 4, 2 times");
}

TEST(ReferenceSeries, ARunOutsideTheReferencesTimesSaysSo) {
    const auto dir = freshDirectory();
    writeFile(dir / "ref.csv", "T,Z\n2,1\n3,1\n");
    const Dictionary dict = Dictionary::fromString("file \"ref.csv\"; time T; columns (Z); scale 1;", "reference");
    ReferenceSeries reference(dict, dir, {"front"});
    reference.compare(1.0, {5.0});
    const auto errors = reference.errors();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_TRUE(std::isnan(errors[0].norms.l1));
    EXPECT_EQ(errors[0].normalisation, "no time of the run within the reference's [2, 3]");
}

TEST(ReferenceSeries, ValueOffsetIsAddedAfterScaling) {
    const auto dir = freshDirectory();
    writeFile(dir / "ref.csv", "t,eta\n0,-0.01\n1,0.03\n");
    const Dictionary dict = Dictionary::fromString("file \"ref.csv\"; time t; columns (eta); valueScale 2; valueOffset 0.6;", "reference");
    const ReferenceSeries reference(dict, dir, {"elevation"});
    EXPECT_DOUBLE_EQ(reference.at(0.0)->at(0), 0.58);
    EXPECT_DOUBLE_EQ(reference.at(0.5)->at(0), 0.62);
}

TEST(ReferenceSeries, BadFilesAreErrorsNamingFileLineAndColumn) {
    const auto dir = freshDirectory();
    const auto read = [&](const std::string& csv, const std::string& columns = "(Z)") {
        writeFile(dir / "ref.csv", csv);
        const Dictionary dict = Dictionary::fromString("file \"ref.csv\"; time t; columns " + columns + ";", "reference");
        return errorOf([&] { ReferenceSeries(dict, dir, {"front"}); });
    };
    EXPECT_NE(read("t,Y\n0,1\n1,2\n").find("has no column 'Z'; its columns are: t, Y"), std::string::npos);
    EXPECT_NE(read("t,Z\n0,1\n1,abc\n").find("ref.csv:3: column 'Z' holds 'abc', not a number"), std::string::npos);
    EXPECT_NE(read("t,Z\n0,1\n").find("has 1 rows of numbers; a reference needs at least 2"), std::string::npos);
    EXPECT_NE(read("t,Z\n0,1\n1,2\n", "(Z Z)").find("lists 2 columns, but this function object compares 1 quantities"), std::string::npos);
    const Dictionary missing = Dictionary::fromString("file \"none.csv\"; time t; columns (Z);", "reference");
    EXPECT_NE(errorOf([&] { ReferenceSeries(missing, dir, {"front"}); }).find("cannot read"), std::string::npos);
}

TEST(ReferenceSeries, RowsThatStepBackAreSortedWithANote) {
    // A digitised curve: line 4 steps back to t = 0.1; two rows at t = 0.3 make a step.
    const auto dir = freshDirectory();
    writeFile(dir / "ref.csv", "t,Z\n0,0\n0.2,2\n0.1,1\n0.3,3\n0.3,5\n0.4,5\n");
    const Dictionary dict = Dictionary::fromString("file \"ref.csv\"; time t; columns (Z);", "reference");
    testing::internal::CaptureStdout();
    const ReferenceSeries reference(dict, dir, {"front"});
    const std::string note = testing::internal::GetCapturedStdout();
    EXPECT_NE(note.find("ref.csv: 1 row steps back in time (line 4); the reference is sorted by time"), std::string::npos) << note;
    EXPECT_DOUBLE_EQ(reference.at(0.15)->front(), 1.5);  // between 0.1 and 0.2, as sorted
    EXPECT_DOUBLE_EQ(reference.at(0.05)->front(), 0.5);
    EXPECT_DOUBLE_EQ(reference.at(0.3)->front(), 3.0);   // the step: the first row of 0.3 from below ...
    EXPECT_DOUBLE_EQ(reference.at(0.35)->front(), 5.0);  // ... the last above
    EXPECT_FALSE(reference.at(0.41));
}

TEST(LineSample, ComparesWithAProfileWhoseCoordinateDecreases) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    for (auto& v : system->fluid[fields::velocity]) v = Vec<2>(0.3, 0.0);
    // Ghia's tables list y from 1 down to 0; a constant profile 0.5 against a uniform 0.3.
    writeFile(dir / "profile.csv", "# from the top\ny,u\n1,0.5\n0.5,0.5\n0,0.5\n");
    const Dictionary dict = Dictionary::fromString(
        "type lineSample; start (0.5 0.02); end (0.5 0.98); points 25; reference { file \"profile.csv\"; coordinate y; axis y; field Ux; columns "
        "(u); scale 2; }",
        "line");
    LineSample<2> line(dict, contextFor(dir, *system));
    line.execute(system->view(), 0.5);
    line.execute(system->view(), 1.0);  // the last execution alone counts
    const auto errors = line.errors();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].quantity, "Ux profile");
    EXPECT_NEAR(errors[0].norms.l1, 0.1, 1e-12);  // |0.3 - 0.5| / 2 at every sample: Shepard keeps constants
    EXPECT_NEAR(errors[0].norms.linf, 0.1, 1e-12);
    EXPECT_NE(errors[0].normalisation.find("25 points at t = 1"), std::string::npos) << errors[0].normalisation;
    writeFile(dir / "profile.csv", "y,u\n1,0.5\n0.5,0.5\n0.7,0.5\n");  // decreasing, then a step back: sorted
    testing::internal::CaptureStdout();
    LineSample<2> sorted(dict, contextFor(dir, *system));
    const std::string note = testing::internal::GetCapturedStdout();
    EXPECT_NE(note.find("profile.csv: 1 row steps back in coordinate (line 4); the reference is sorted by coordinate"), std::string::npos) << note;
}

TEST(FieldErrorNorm, NormsOfAKnownPerturbationOfTheExactField) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    const Dictionary dict =
        Dictionary::fromString("type errorNorm; field U; scale 2; solution { type taylorGreen; U 1; L 1; nu 0.01; }", "velocityError");
    FieldErrorNorm<2> error(dict, contextFor(dir, *system));
    const double t = 0.3;
    auto& v = system->fluid[fields::velocity];
    const TaylorGreen2D<2> exact(dict.subDict("solution"));
    for (std::size_t i = 0; i < system->fluid.size(); ++i) v[i] = exact.velocity(system->fluid.position[i], t);
    v[17].x() += 0.1;  // one particle off by 0.1
    const double count = n * n;
    const ErrorNorms norms = error.norms(system->view(), t);
    EXPECT_NEAR(norms.l1, 0.1 / count / 2.0, 1e-12);
    EXPECT_NEAR(norms.l2, std::sqrt(0.01 / count) / 2.0, 1e-12);
    EXPECT_NEAR(norms.linf, 0.1 / 2.0, 1e-12);
    // Over the run: the same at two executions gives the same space-time norms.
    error.execute(system->view(), t);
    error.execute(system->view(), t);
    EXPECT_NEAR(error.errors().at(0).norms.l2, norms.l2, 1e-12);
}

TEST(FieldErrorNorm, PressureUpToAConstantAndASolutionWithoutPressure) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    const Dictionary dict =
        Dictionary::fromString("type errorNorm; field p; subtractMean yes; solution { type hydrostatic; freeSurfaceHeight 1; }", "pressureError");
    FieldErrorNorm<2> error(dict, contextFor(dir, *system));
    auto& p = system->fluid[fields::pressure];
    for (std::size_t i = 0; i < system->fluid.size(); ++i) p[i] = 1234.0 + 1000.0 * 9.81 * (1.0 - system->fluid.position[i].y());
    EXPECT_NEAR(error.norms(system->view(), 1.0).linf, 0.0, 1e-9);
    const Dictionary noPressure = Dictionary::fromString("type errorNorm; field p; solution { type couette; V0 1; L 1; nu 1; }", "pressureError");
    EXPECT_NE(errorOf([&] { FieldErrorNorm<2>(noPressure, contextFor(dir, *system)); }).find("the couette solution has no pressure field"),
              std::string::npos);
}

TEST(ColumnHeight, GaugesReadTheBlockHeightAboveThemAndZeroWhenDry) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    const Dictionary dict = Dictionary::fromString("type columnHeight; points ((0.5 0) (0.5 0.2) (1.05 0));", "gauges");
    ColumnHeight<2> gauges(dict, contextFor(dir, *system));
    const std::vector<double> h = gauges.heights(system->view());
    EXPECT_NEAR(h[0], 1.0, 1e-12);  // the top particle at 0.98 plus half a spacing
    EXPECT_NEAR(h[1], 0.8, 1e-12);
    EXPECT_EQ(h[2], 0.0);  // 0.07 from the nearest column, beyond the radius h = 0.052
}

TEST(WaveGauge, ReadsTheBlockSurfaceWhereTheVolumeFractionFallsThroughAHalf) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    const Dictionary dict = Dictionary::fromString("type waveGauge; points ((0.5 0) (0.5 0.2) (1.05 0));", "gauges");
    WaveGauge<2> gauges(dict, contextFor(dir, *system));
    const std::vector<double> eta = gauges.elevations(system->view(), 0.0);
    // The block's continuum surface is at 1.0 (top row at 0.98, half a spacing below); the
    // lattice's kernel sum crosses 1/2 within a few hundredths of a spacing of it.
    EXPECT_NEAR(eta[0], 1.0, 0.05 * dx);
    EXPECT_NEAR(eta[1], 0.8, 0.05 * dx);
    EXPECT_EQ(eta[2], 0.0);  // 1.25 dx beside the block's side: the fraction stays below 1/2
    // A higher threshold reads the surface lower.
    WaveGauge<2> strict(Dictionary::fromString("type waveGauge; points ((0.5 0)); threshold 0.9;", "gauges"), contextFor(dir, *system));
    EXPECT_LT(strict.elevations(system->view(), 0.0)[0], eta[0] - 0.2 * dx);
}

TEST(WaveGauge, ASplashedParticleAboveTheSurfaceDoesNotReadAsTheLevel) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    system->fluid.position[0] = Vec<2>(0.5, 1.09);  // on the gauge's line, beyond the top row's support
    system->evaluateRates(0.0);
    WaveGauge<2> gauge(Dictionary::fromString("type waveGauge; points ((0.5 0));", "gauge"), contextFor(dir, *system));
    const ColumnHeight<2> highest(Dictionary::fromString("type columnHeight; points ((0.5 0));", "column"), contextFor(dir, *system));
    EXPECT_NEAR(gauge.elevations(system->view(), 0.0)[0], 1.0, 0.05 * dx);
    EXPECT_NEAR(highest.heights(system->view())[0], 1.11, 1e-12);  // the highest particle does
}

TEST(WaveGauge, GaugesOnAMovingPatchFollowItAndWriteTheirSeries) {
    const auto dir = freshDirectory();
    auto system = makeBlock(std::make_unique<Translation<2>>(Dictionary::fromString("velocity (0.3 0);", "motion")));
    const Dictionary dict = Dictionary::fromString("type waveGauge; points ((0.85 0)); patch tank; length 1.05;", "gauges");
    WaveGauge<2> moving(dict, contextFor(dir, *system));
    WaveGauge<2> fixed(Dictionary::fromString("type waveGauge; points ((0.85 0));", "gauges"), contextFor(dir, *system));
    EXPECT_NEAR(moving.elevations(system->view(), 0.0)[0], 1.0, 0.05 * dx);
    EXPECT_EQ(moving.elevations(system->view(), 1.0)[0], 0.0);  // carried to x = 1.15, beside the block
    EXPECT_NEAR(fixed.elevations(system->view(), 1.0)[0], 1.0, 0.05 * dx);
    moving.execute(system->view(), 0.0);
    const auto [header, row] = headerAndFirstRow(dir / "postProcessing/object/0/elevation.dat");
    EXPECT_EQ(header, "# time eta(0.85 0)");
    EXPECT_EQ(row.substr(0, 4), "0 0.");  // just below 1.0
}

// A serial run's reductions that count their collectives.
struct CountedReductions : Reductions {
    mutable int collectives = 0;
    void max(std::span<double>) const override { ++collectives; }
};

TEST(WaveGauge, TakesEveryGaugesSamplesInOneCollectivePerStage) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    const CountedReductions counted;
    const FunctionObjectContext<2> context = contextFor(dir, *system);
    const FunctionObjectContext<2> countedContext{context.caseDirectory, context.outputDirectory, context.rho0, context.system, counted};
    WaveGauge<2> gauges(Dictionary::fromString("type waveGauge; points ((0.1 0) (0.3 0.1) (0.5 0.2) (0.7 0.3) (0.9 0.4) (1.05 0));", "gauges"),
                        countedContext);
    counted.collectives = 0;
    const std::vector<double> eta = gauges.elevations(system->view(), 0.0);
    // The scan, then the bisection from dx/4 to dx/1000 in 8 rounds, however many gauges.
    EXPECT_EQ(counted.collectives, 1 + 8);
    for (std::size_t k = 0; k < 5; ++k) EXPECT_NEAR(eta[k], 1.0 - 0.1 * static_cast<double>(k), 0.05 * dx);
    EXPECT_EQ(eta[5], 0.0);
}

TEST(WaveGauge, BadThresholdPatchOrLineAreErrorsBeforeTheFirstStep) {
    const auto dir = freshDirectory();
    auto system = makeBlock(std::make_unique<Translation<2>>(Dictionary::fromString("velocity (0.3 0);", "motion")));
    const auto error = [&](const std::string& entries) {
        return errorOf([&] { WaveGauge<2>(Dictionary::fromString("type waveGauge; " + entries, "gauges"), contextFor(dir, *system)); });
    };
    EXPECT_NE(error("points ((0.5 0)); threshold 1.5;").find("1.5 is not a volume fraction between 0 and 1"), std::string::npos);
    EXPECT_NE(error("points ((0.5 0)); patch lid;").find("no patch 'lid'; the patches are: tank"), std::string::npos);
    EXPECT_NE(error("points ((0.5 0)); length -1;").find("length"), std::string::npos);
    EXPECT_NE(error("points ((2 0));").find("gauge 0 at (2 0) lies outside the domain"), std::string::npos);
}

TEST(WallPressureSensors, ExtrapolateTheFluidWhereTheModelSetsNoWallPressure) {
    // Adami's extrapolation of a hydrostatic field at uniform density is rho0 g H exactly.
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(std::make_unique<RepulsiveWall<2>>(MonaghanKajtar2009{1e-9, dx, 0.0, 0.0}));
    const Dictionary dict = Dictionary::fromString("type wallPressure; patch floor; points ((0.5 0) (0.3 0)); size 0.1;", "sensors");
    const WallPressureSensors<2> sensors(dict, contextFor(dir, *system));
    for (const double p : sensors.pressures(system->view(), 0.0)) EXPECT_NEAR(p, 1000.0 * 9.81, 1e-9);
}

TEST(WallPressureSensors, AverageTheModelsWallPressureOverTheirFootprintByArea) {
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(dummyParticles());
    auto& p = system->walls[fields::pressure];
    for (std::size_t j = 0; j < p.size(); ++j) p[j] = 100.0 * system->walls.position[j].x();
    const auto read = [&](const std::string& entries) {
        return WallPressureSensors<2>(Dictionary::fromString("type wallPressure; patch floor; " + entries, "sensors"), contextFor(dir, *system))
            .pressures(system->view(), 0.0);
    };
    EXPECT_NEAR(read("points ((0.5 0)); size 0.18;")[0], 50.0, 1e-9);    // 0.44 ... 0.56, symmetric
    EXPECT_NEAR(read("points ((0.51 0)); size 0.001;")[0], 52.0, 1e-9);  // smaller than the spacing: the nearest particle
    system->walls[fields::area][13] = 3.0 * dx;                          // the particle at x = 0.44 stands for three spacings
    EXPECT_NEAR(read("points ((0.5 0)); size 0.18;")[0], (3.0 * 44.0 + 48.0 + 52.0 + 56.0) / 6.0, 1e-9);
}

TEST(WallPressureSensors, TheFootprintIsMeasuredAlongTheWallNotAcrossIt) {
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(dummyParticles());
    auto& p = system->walls[fields::pressure];
    for (std::size_t j = 0; j < p.size(); ++j) {
        p[j] = 100.0 * system->walls.position[j].x();
        system->walls.position[j].y() = -0.5 * dx;  // layer 0 of a layered wall, half a spacing below the surface y = 0
    }
    // Particles at 0.48 and 0.52 lie 0.02 from the centre along the wall and 0.028 in space.
    const WallPressureSensors<2> sensor(Dictionary::fromString("type wallPressure; patch floor; points ((0.5 0)); size 0.048;", "sensors"),
                                        contextFor(dir, *system));
    EXPECT_NEAR(sensor.pressures(system->view(), 0.0)[0], 50.0, 1e-9);
}

TEST(WallPressureSensors, SourceFluidExtrapolatesWhereTheModelSetsAPressure) {
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(dummyParticles());
    system->walls[fields::pressure].assign(system->walls.size(), -1.0);  // what the model would read: ignored
    const WallPressureSensors<2> sensor(
        Dictionary::fromString("type wallPressure; patch floor; points ((0.5 0)); size 0.1; source fluid;", "sensors"), contextFor(dir, *system));
    EXPECT_NEAR(sensor.pressures(system->view(), 0.0)[0], 1000.0 * 9.81, 1e-9);
}

TEST(WallPressureSensors, SensorsMoveWithTheirPatch) {
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(dummyParticles(), std::make_unique<Translation<2>>(Dictionary::fromString("velocity (0.3 0);", "motion")));
    const WallPressureSensors<2> sensor(Dictionary::fromString("type wallPressure; patch floor; points ((0.5 0)); size 0.18;", "sensors"),
                                        contextFor(dir, *system));
    system->evaluateRates(0.5);  // the floor moved by 0.15
    auto& p = system->walls[fields::pressure];
    for (std::size_t j = 0; j < p.size(); ++j) p[j] = 100.0 * system->walls.position[j].x();
    EXPECT_NEAR(sensor.pressures(system->view(), 0.5)[0], 65.0, 1e-9);
}

TEST(WallPressureSensors, TheTimeWindowAveragesTheSignalTrailingAndWritesBoth) {
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(dummyParticles());
    WallPressureSensors<2> sensor(Dictionary::fromString("type wallPressure; patch floor; points ((0.5 0)); timeWindow 0.3;", "sensors"),
                                  contextFor(dir, *system));
    // A signal rising as t: its trailing mean is t/2 until the window fills, then t - 0.15.
    std::vector<double> mean;
    for (int k = 0; k <= 10; ++k) mean.push_back(sensor.averaged(0.1 * k, {0.1 * k})[0]);
    EXPECT_NEAR(mean[0], 0.0, 1e-12);
    EXPECT_NEAR(mean[2], 0.1, 1e-12);
    EXPECT_NEAR(mean[10], 0.85, 1e-12);
    WallPressureSensors<2> writing(Dictionary::fromString("type wallPressure; patch floor; points ((0.5 0)); timeWindow 0.3;", "sensors"),
                                   contextFor(dir, *system));
    writing.execute(system->view(), 0.0);
    const auto [header, row] = headerAndFirstRow(dir / "postProcessing/object/0/pressure.dat");
    EXPECT_EQ(header, "# time p(0.5 0) pAveraged(0.5 0)");
}

TEST(WallPressureSensors, BadPatchSensorOrSizeAreErrorsBeforeTheFirstStep) {
    const auto dir = freshDirectory();
    auto system = makeBlockOnAFloor(dummyParticles());
    const auto error = [&](const std::string& entries) {
        return errorOf([&] { WallPressureSensors<2>(Dictionary::fromString("type wallPressure; " + entries, "sensors"), contextFor(dir, *system)); });
    };
    EXPECT_NE(error("patch lid; points ((0.5 0));").find("no patch 'lid'; the patches are: floor"), std::string::npos);
    EXPECT_NE(error("patch floor; points ((0.52 0.5));").find("sensor 0 at (0.52 0.5) is 0.5 from the surface of patch 'floor'"), std::string::npos);
    EXPECT_NE(error("patch floor; points ((0.5 0)); size 0;").find("size"), std::string::npos);
    EXPECT_NE(error("patch floor; points ((0.5 0)); timeWindow -1;").find("timeWindow"), std::string::npos);
    EXPECT_NE(error("patch floor; points ((0.5 0)); source wall;").find("unknown source 'wall'; valid sources are: model"), std::string::npos);
}

TEST(FieldTotals, MassEnergyAndMomentumOfTheBlock) {
    const auto dir = freshDirectory();
    auto system = makeBlock();
    for (auto& v : system->fluid[fields::velocity]) v = Vec<2>(2.0, 0.0);
    FieldTotals<2> totals(Dictionary::fromString("type fieldTotals;", "totals"), contextFor(dir, *system));
    totals.execute(system->view(), 0.0);
    const auto [header, row] = headerAndFirstRow(dir / "postProcessing/object/0/totals.dat");
    EXPECT_EQ(header, "# time mass kineticEnergy momentum_x momentum_y");
    // Mass 1000 kg (1 m^2 at rho0 1000), energy 1000 * 4 / 2, momentum 2000.
    EXPECT_EQ(row, "0 1000 2000 2000 0");
}
