// The deficiency correction with its defaults in the flows it must hold, coarsened: the first
// impact of the standard dam break, still water, and a 3D tank. Penetrations are counted at
// every step (wallPenetrations), not only at written times.
#include "driver/Simulation.hpp"
#include "generation/ParticleGenerator.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace sph::test;

namespace {

// The rows of a whitespace-separated time series.
std::vector<std::vector<double>> rows(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<double>> table;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        table.emplace_back();
        for (double v; row >> v;) table.back().push_back(v);
    }
    return table;
}

// The most fluid particles behind a wall at any step, and the number of steps counted.
std::pair<int, std::size_t> mostBehindWall(const std::filesystem::path& caseDirectory) {
    const auto table = rows(caseDirectory / "postProcessing/leaks/0/penetrations.dat");
    int most = -1;
    for (const auto& row : table) most = std::max(most, static_cast<int>(row[1]));
    return {most, table.size()};
}

// The mean of column `column` of p.dat over t sqrt(g/H) in [lo, hi), over rho g H.
double meanPressure(const std::vector<std::vector<double>>& table, std::size_t column, double lo, double hi) {
    const double H = 0.6, g = 9.81;
    double sum = 0.0;
    int count = 0;
    for (const auto& row : table) {
        const double T = row[0] * std::sqrt(g / H);
        if (T >= lo && T < hi) sum += row[column], ++count;
    }
    return count ? sum / count / (1000.0 * g * H) : NAN;
}

}  // namespace

TEST(CorrectionFlows, DamBreakImpactAtTheDownstreamCornerHoldsWithoutPenetration) {
    // damBreakWallPressure2D at H/dx = 20 (800 particles) to T = 4, through the first impact
    // (T = 2.4), where the paper's calibration blew up (T = 2.58 on c09449c). The pressure at P1
    // after the impact (T = 3-4, time-averaged) is 1.12 in the delta-SPH reference; measured 1.37
    // here (1.39 at H/dx = 40; dummy particles 1.06 and 1.09): it over-reads the bottom corner,
    // doc/boundaryFindings.md.
    const auto dir = copyCase("damBreakWallPressure2D");
    setEntry(dir / "system/generateParticlesDict", "spacing", "0.03");
    setEntry(dir / "system/controlDict", "endTime", "0.99");
    sph::generateParticles(dir, false);
    sph::runCase(dir);
    const auto [most, steps] = mostBehindWall(dir);
    EXPECT_EQ(most, 0);
    EXPECT_GT(steps, 3000u) << "counted at every step";
    const auto sensors = rows(dir / "postProcessing/sensors/0/p.dat");
    ASSERT_GT(sensors.back()[0], 0.98);
    const double p1 = meanPressure(sensors, 1, 3.0, 4.0);
    EXPECT_NEAR(p1, 1.12, 0.3) << "against the reference";
    EXPECT_NEAR(p1, 1.37, 0.05) << "the documented figure";
}

TEST(CorrectionFlows, StillWaterSettlesOnOneLayerOfWallParticles) {
    // hydrostaticTank2D at dx = 0.05 with the correction on one layer on the wall, to t = 2 (the
    // gravity ramp ends at t = 1): the water settles, nothing passes the wall at any step, and
    // the centre line holds rho g (H - z).
    const auto dir = copyCase("hydrostaticTank2D");
    setEntry(dir / "system/generateParticlesDict", "spacing", "0.05");
    replaceInFile(dir / "system/generateParticlesDict", "tank    { type boxWalls; min (0 0); max (2 1); layers 4; open (yMax); }",
                  "tank    { type boxWalls; min (0 0); max (2 1); layers 1; firstLayerOffset 0; open (yMax); }");
    writeFile(dir / "constant/boundaryProperties", "tank { type deficiencyCorrectionBoundaryIntegral; }\n");
    replaceInFile(dir / "system/controlDict", "functions\n{",
                  "functions\n{\n    leaks { type wallPenetrations; }\n    totals { type fieldTotals; executeInterval 0.5; }");
    sph::generateParticles(dir, false);
    sph::runCase(dir);
    EXPECT_EQ(mostBehindWall(dir).first, 0);
    const auto totals = rows(dir / "postProcessing/totals/0/totals.dat");
    ASSERT_DOUBLE_EQ(totals.back()[0], 2.0);
    const double kineticPerMass = totals.back()[2] / totals.back()[1] / 0.9;  // over g H
    EXPECT_LT(kineticPerMass, 1e-5);                                          // measured 3.2e-6
    const auto pressure = rows(dir / "postProcessing/pressure/0/error.dat");
    EXPECT_LT(pressure.back()[1], 0.03) << "L2 centre-line pressure error over rho g H (measured 0.023)";
}
