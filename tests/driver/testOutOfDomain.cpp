// controlDict's outOfDomain: a fluid particle that leaves the domain stops the run (stop, the
// default) or is removed while the run goes on (remove).
#include "core/FatalError.hpp"
#include "driver/CaseDirectory.hpp"
#include "driver/OutOfDomain.hpp"
#include "driver/Simulation.hpp"
#include "generation/ParticleGenerator.hpp"
#include "io/ParticleFile.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace sph::test;

TEST(OutOfDomain, RemovesTheParticlesOutsideTheDomainAndKeepsTheOthersInOrder) {
    sph::ParticleSet<2> fluid("fluid");
    fluid.resize(5);
    auto& density = fluid.add(sph::fields::density, 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<sph::Vec<2>> positions{{0.5, 0.5}, {1.2, 0.5}, {nan, 0.5}, {0.5, -0.1}, {1.0, 0.0}};
    for (std::size_t i = 0; i < 5; ++i) {
        fluid.position[i] = positions[i];
        fluid.globalId[i] = 10 + static_cast<std::int64_t>(i);
        density[i] = 1000.0 + static_cast<double>(i);
    }
    // Outside: past xMax and below yMin; on the domain's edge is inside; a NaN is the blow-up check's.
    const std::vector<std::uint32_t> outside = sph::fluidOutside<2>(fluid, sph::Vec<2>(0, 0), sph::Vec<2>(1, 1));
    EXPECT_EQ(outside, (std::vector<std::uint32_t>{1, 3}));
    sph::removeFluid(fluid, outside);
    ASSERT_EQ(fluid.size(), 3u);
    EXPECT_EQ(fluid.ownedCount(), 3u);
    const std::vector<std::int64_t> ids(fluid.globalId.begin(), fluid.globalId.end());
    EXPECT_EQ(ids, (std::vector<std::int64_t>{10, 12, 14}));
    EXPECT_EQ(fluid[sph::fields::density][1], 1002.0);
    EXPECT_EQ(fluid[sph::fields::density][2], 1004.0);
}

namespace {

// damBreak2D at dx = a/20 with its column thrown upwards at 3 m/s out of the open tank: its top
// passes the domain's top (0.2 m) within 0.03 s.
std::filesystem::path thrownColumn(const std::string& outOfDomain) {
    const auto dir = copyCase("damBreak2D", outOfDomain);
    replaceInFile(dir / "system/generateParticlesDict", "spacing     0.00142875;", "spacing     0.0028575;");
    replaceInFile(dir / "system/generateParticlesDict", "max ($a 0.1143); }", "max ($a 0.1143); velocity (0 3); }");
    replaceInFile(dir / "system/controlDict", "endTime         0.2; ", "endTime         0.05; outOfDomain " + outOfDomain + ";");
    replaceInFile(dir / "system/controlDict", "writeInterval   0.01;", "writeInterval   0.025;");
    sph::generateParticles(dir, false);
    return dir;
}

}  // namespace

TEST(OutOfDomain, StopNamesTheParticleAndTheWayToRemoveSuchParticles) {
    const auto dir = thrownColumn("stop");
    try {
        sph::runCase(dir);
        FAIL() << "the column left the domain and the run went on";
    } catch (const sph::FatalError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("left the domain"), std::string::npos) << message;
        EXPECT_NE(message.find("outOfDomain remove"), std::string::npos) << message;
    }
}

TEST(OutOfDomain, RemoveTakesOutTheParticlesThatLeftAndRunsOn) {
    const auto dir = thrownColumn("remove");
    testing::internal::CaptureStdout();
    sph::runCase(dir);
    const std::string printed = testing::internal::GetCapturedStdout();
    sph::StateHeader header;
    const auto start = sph::readParticleFile<2>(dir / "0/fluid.vtu", "fluid", header);
    const auto end = sph::readParticleFile<2>(dir / "0.05/fluid.vtu", "fluid", header);
    ASSERT_LT(end.size(), start.size());
    for (std::size_t i = 0; i < end.size(); ++i) EXPECT_LE(end.position[i].y(), 0.2);
    // Every removal was printed: the last line's count is every particle that left.
    const std::size_t last = printed.rfind("left the domain and");
    ASSERT_NE(last, std::string::npos) << printed;
    const std::size_t soFar = printed.find(" so far)", last);
    const std::size_t open = printed.rfind('(', soFar);
    EXPECT_EQ(std::stoul(printed.substr(open + 1, soFar - open - 1)), start.size() - end.size()) << printed.substr(last, 100);
}
