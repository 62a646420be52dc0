// A run that blows up stops with the step, time, particle and quantity, and keeps what it wrote.
#include "core/FatalError.hpp"
#include "driver/BlowUpCheck.hpp"
#include "driver/CaseDirectory.hpp"
#include "driver/Simulation.hpp"
#include "generation/ParticleGenerator.hpp"
#include "io/ParticleFile.hpp"
#include "support/CaseFixture.hpp"
#include "support/RestoreThreadCount.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>

using namespace sph::test;

namespace {

// The hydrostatic tank at dx = 0.05 (h = 0.06, c0 = 30 m/s) with a fixed step far above the
// acoustic limit (0.01 s is an acoustic Courant number of 5).
std::string blowUp(const std::string& integrator, const std::string& step) {
    const auto dir = copyCase("hydrostaticTank2D");
    replaceInFile(dir / "system/generateParticlesDict", "spacing     0.02;", "spacing     0.05;");
    replaceInFile(dir / "system/timeIntegration", "integrator  { type symplectic; }", "integrator  { type " + integrator + "; }");
    replaceInFile(dir / "system/timeIntegration", "courant     0.2;", "courant     0.2; fixedDeltaT " + step + ";");
    replaceInFile(dir / "system/controlDict", "writeInterval   0.25;", "writeInterval   0.02;");
    sph::generateParticles(dir, false);
    try {
        sph::runCase(dir);
    } catch (const sph::FatalError& error) {
        // The last time written before the blow-up holds a good state.
        const sph::TimeDirectory latest = sph::findTimeDirectories(dir).back();
        EXPECT_GT(latest.time, 0.0);
        sph::StateHeader header;
        const auto fluid = sph::readParticleFile<2>(latest.path / "fluid.vtu", "fluid", header);
        for (std::size_t i = 0; i < fluid.size(); ++i) {
            EXPECT_TRUE(fluid.position[i].allFinite() && fluid[sph::fields::velocity][i].allFinite());
            EXPECT_GT(fluid[sph::fields::density][i], 500.0);
        }
        return error.what();
    }
    return "no error";
}

}  // namespace

TEST(BlowUp, NativeIntegratorStopsWithStepTimeParticleAndQuantity) {
    const std::string message = blowUp("symplectic", "0.01");
    EXPECT_NE(message.find("blew up at step"), std::string::npos) << message;
    EXPECT_NE(message.find("time"), std::string::npos) << message;
    EXPECT_NE(message.find("fluid particle id"), std::string::npos) << message;
    EXPECT_TRUE(message.find("density") != std::string::npos || message.find("velocity") != std::string::npos ||
                message.find("left the domain") != std::string::npos)
        << message;
}

TEST(BlowUp, SundialsIntegratorStopsWithTheFailureAndItsCause) {
    const std::string message = blowUp("arkodeERK", "0.02");
    EXPECT_NE(message.find("blew up at"), std::string::npos) << message;
    EXPECT_NE(message.find("particle id"), std::string::npos) << message;
}

// Every fault is named, and the report is the first faulty particle in storage order with any
// number of threads (the check runs in parallel).
TEST(BlowUp, CheckNamesTheFirstFaultyParticleAndItsFault) {
    const sph::test::RestoreThreadCount restore;
    const sph::FluidStateLimits limits{10.0, 1000.0};
    const sph::Vec<2> lo(0.0, 0.0), hi(1.0, 1.0);
    sph::ParticleSet<2> fluid("fluid");
    fluid.resize(1000);
    auto& velocity = fluid.add(sph::fields::velocity, sph::Vec<2>(1.0, -1.0));
    auto& density = fluid.add(sph::fields::density, 1000.0);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
        fluid.position[i] = sph::Vec<2>(0.001 * static_cast<double>(i), 0.5);
        fluid.globalId[i] = 5000 + static_cast<std::int64_t>(i);
    }
    const auto report = [&] {
        std::string first;
        for (const int threads : {1, 2, 3, 7}) {
            omp_set_num_threads(threads);
            try {
                sph::checkFluidState(fluid, lo, hi, limits, 12, 0.25);
            } catch (const sph::FatalError& error) {
                if (first.empty()) first = error.what();
                EXPECT_EQ(error.what(), first) << threads << " threads";
                continue;
            }
            EXPECT_TRUE(first.empty()) << threads << " threads found nothing";
        }
        return first;
    };
    EXPECT_EQ(report(), "");

    // Faults further on in storage order come first, so that a report of the last one fails.
    fluid.position[900] = sph::Vec<2>(0.9, std::nan(""));
    velocity[800] = sph::Vec<2>(std::numeric_limits<double>::infinity(), 0.0);
    velocity[700] = sph::Vec<2>(11.0, 0.0);
    density[600] = 499.0;
    fluid.position[500] = sph::Vec<2>(0.5, 1.01);
    EXPECT_EQ(report(),
              "error: the run blew up at step 12, time 0.25: fluid particle id 5500 at (0.5 1.01) left the domain [(0 0), (1 1)].\n"
              "    The last written time is kept; reduce the time step (courant) or check the case (a splash over the walls: enlarge "
              "the domain, or have such particles removed with `outOfDomain remove;` in system/controlDict).");
    fluid.position[500] = sph::Vec<2>(0.5, 0.5);
    EXPECT_EQ(report().find("outOfDomain"), std::string::npos);  // the hint is for particles that left the domain only
    EXPECT_NE(report().find("particle id 5600 at (0.6 0.5) has density 499, outside [0.5, 2] rho0 = [500, 2000]"), std::string::npos);
    density[600] = std::nan("");
    EXPECT_NE(report().find("particle id 5600 at (0.6 0.5) has density nan"), std::string::npos);
    density[600] = 1000.0;
    EXPECT_NE(report().find("particle id 5700 at (0.7 0.5) moves at 11, faster than the speed of sound c0 = 10"), std::string::npos);
    velocity[700] = sph::Vec<2>(1.0, -1.0);
    EXPECT_NE(report().find("particle id 5800 at (0.8 0.5) has a non-finite velocity"), std::string::npos);
    velocity[800] = sph::Vec<2>(1.0, -1.0);
    EXPECT_NE(report().find("particle id 5900 at (0.9 nan) has a non-finite position"), std::string::npos);
    fluid.position[900] = sph::Vec<2>(0.9, 0.5);
    EXPECT_EQ(report(), "");
}
