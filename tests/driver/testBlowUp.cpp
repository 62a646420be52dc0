// A run that blows up stops with the step, time, particle and quantity, and keeps what it wrote.
#include "core/FatalError.hpp"
#include "driver/CaseDirectory.hpp"
#include "driver/Simulation.hpp"
#include "generation/ParticleGenerator.hpp"
#include "io/ParticleFile.hpp"
#include "support/CaseFixture.hpp"

#include <gtest/gtest.h>

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
            EXPECT_TRUE(fluid.position[i].allFinite() && fluid.vector("velocity")[i].allFinite());
            EXPECT_GT(fluid.scalar("density")[i], 500.0);
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
