// Restart and output safety: a run stopped at a written time (endTime reached, a stop signal,
// or kill -9) and restarted with `startFrom latestTime` ends in the state of the uninterrupted
// run, to the last bit for the native integrators; a killed run leaves only complete output.
#include "driver/Simulation.hpp"
#include "generation/ParticleGenerator.hpp"
#include "io/ParticleFile.hpp"
#include "support/CaseFixture.hpp"
#include "support/SolverProcess.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <thread>

using namespace sph::test;

namespace {

double magnitude(double value) { return std::abs(value); }
double magnitude(const sph::Vec<2>& value) { return value.norm(); }

// Every field of both particle sets of two state directories, compared bit for bit (or to
// `tolerance`, relative to the field's largest magnitude).
void expectSameState(const std::filesystem::path& a, const std::filesystem::path& b, double tolerance = 0.0) {
    for (const char* part : {"fluid.vtu", "walls.vtu"}) {
        sph::StateHeader headerA, headerB;
        const auto setA = sph::readParticleFile<2>(a / part, "a", headerA);
        const auto setB = sph::readParticleFile<2>(b / part, "b", headerB);
        ASSERT_EQ(setA.size(), setB.size()) << part;
        EXPECT_EQ(headerA.time, headerB.time) << part;
        EXPECT_EQ(headerA.step, headerB.step) << part;
        EXPECT_EQ(setA.globalId, setB.globalId) << part;
        const auto compare = [&](const std::string& name, const auto& valuesA, const auto& valuesB) {
            ASSERT_EQ(valuesA.size(), valuesB.size()) << part << " " << name;
            double scale = 0.0, largest = 0.0;
            for (std::size_t i = 0; i < valuesA.size(); ++i) {
                scale = std::max(scale, magnitude(valuesA[i]));
                largest = std::max(largest, magnitude(valuesA[i] - valuesB[i]));
            }
            if (tolerance == 0.0)
                EXPECT_EQ(largest, 0.0) << part << " field " << name << " differs";
            else
                EXPECT_LE(largest, tolerance * scale) << part << " field " << name;
        };
        compare("position", setA.position, setB.position);
        for (const auto& [name, field] : setA.scalars()) compare(name, field.values, setB[sph::ScalarField{name}]);
        for (const auto& [name, field] : setA.vectors()) compare(name, field.values, setB[sph::VectorField{name}]);
        for (const auto& [name, field] : setA.integers()) EXPECT_EQ(field.values, setB[sph::IntegerField{name}]) << part << " " << name;
    }
}

}  // namespace

namespace {

// The dam break at dx = a/10 (200 fluid particles), written every 0.01 s.
std::filesystem::path smallDamBreak(const std::string& variant, const std::string& integrator, const std::string& endTime) {
    const auto dir = copyCase("damBreak2D", variant);
    setEntry(dir / "system/generateParticlesDict", "spacing", "0.005715");
    setEntry(dir / "system/controlDict", "endTime", endTime);
    writeFile(dir / "system/timeIntegration", "integrator { type " + integrator + "; }\ncourant 0.2;\n");
    sph::generateParticles(dir, false);
    return dir;
}

// Runs to `endTime` in process, then again to `laterEndTime` from the latest time.
void runInTwoParts(const std::filesystem::path& dir, const std::string& laterEndTime) {
    sph::runCase(dir);
    setEntry(dir / "system/controlDict", "endTime", laterEndTime);
    sph::runCase(dir);
}

}  // namespace

TEST(Restart, NativeIntegratorsContinueBitForBit) {
    // 0.04 s in one run against 0.02 s and a restart: every field of both particle sets equal.
    // Verlet's restart needs its previous level and its place in the Euler cycle (written with
    // the state); the sort by cell every 10 steps must fall on the same steps.
    for (const std::string integrator : {"symplectic", "verlet", "leapfrog", "predictorCorrector"}) {
        SCOPED_TRACE(integrator);
        const auto whole = smallDamBreak(integrator + "/whole", integrator, "0.04");
        sph::runCase(whole);
        const auto parts = smallDamBreak(integrator + "/parts", integrator, "0.02");
        runInTwoParts(parts, "0.04");
        expectSameState(whole / "0.04", parts / "0.04");
    }
}

TEST(Restart, ParticleShiftingContinuesBitForBit) {
    // The shift after each step is computed from the state alone: a restart repeats it. The
    // leapfrog's end-of-step rates, read at the shifted positions by its next kick, are written.
    for (const std::string integrator : {"symplectic", "leapfrog"}) {
        SCOPED_TRACE(integrator);
        const auto withShifting = [&](const std::filesystem::path& dir) {
            std::ofstream(dir / "system/sphSchemes", std::ios::app) << "particleShifting { type sun; }\n";
            return dir;
        };
        const auto whole = withShifting(smallDamBreak(integrator + "/shiftedWhole", integrator, "0.04"));
        sph::runCase(whole);
        const auto parts = withShifting(smallDamBreak(integrator + "/shiftedParts", integrator, "0.02"));
        runInTwoParts(parts, "0.04");
        expectSameState(whole / "0.04", parts / "0.04");
    }
}

namespace {

// A shipped case at a coarser spacing, run to `endTime` in one go and to `midTime` plus a
// restart: the two end states must agree to the bit.
void expectRestartContinuesExactly(const std::string& caseName, const std::string& spacing, const std::string& midTime, const std::string& endTime,
                                   const std::string& boundaryProperties = "") {
    const auto prepare = [&](const std::string& variant, const std::string& firstEndTime) {
        const auto dir = copyCase(caseName, variant);
        if (!boundaryProperties.empty()) writeFile(dir / "constant/boundaryProperties", boundaryProperties);
        setEntry(dir / "system/generateParticlesDict", "spacing", spacing);
        setEntry(dir / "system/controlDict", "endTime", firstEndTime);
        sph::generateParticles(dir, false);
        return dir;
    };
    const auto whole = prepare("whole", endTime);
    sph::runCase(whole);
    const auto parts = prepare("parts", midTime);
    runInTwoParts(parts, endTime);
    expectSameState(whole / endTime, parts / endTime);
}

}  // namespace

TEST(Restart, FreeBodyContinuesBitForBit) {
    // The sinking cylinder at dx = 0.02: the body's state and its load history are written in
    // the state's header.
    expectRestartContinuesExactly("sinkingCylinder2D", "0.02", "0.02", "0.04");
}

TEST(Restart, DeformingWallWithCorrectionContinuesBitForBit) {
    // The deforming tank at dx = 0.05: its walls move from their initial positions, which the
    // state keeps; the correction's wall pressures are recomputed from the fluid.
    expectRestartContinuesExactly("deformingTank2D", "0.05", "0.05", "0.1");
}

TEST(Restart, DeformingWallWithSmoothedCorrectionContinuesBitForBit) {
    // The paper's calibration smoothed in time: the written C_j carry its history.
    expectRestartContinuesExactly("deformingTank2D", "0.05", "0.05", "0.1",
                                  "tank { type deficiencyCorrection; calibration calibrated; temporalSmoothing 0.05; "
                                  "motion { type gaussianBulge; centre (1 0); amplitude 0.1; width 0.2; period 2; } }\n");
}

TEST(Restart, AdaptiveArkodeContinuesWithinItsTolerance) {
    // The restart keeps the step size it would take next but rebuilds the error controller's history, so
    // the runs agree to the tolerance, not to the bit.
    const std::string integrator = "arkodeERK; adaptive yes; relativeTolerance 1e-6; absoluteTolerance 1e-8";
    const auto whole = smallDamBreak("whole", integrator, "0.04");
    sph::runCase(whole);
    const auto parts = smallDamBreak("parts", integrator, "0.02");
    runInTwoParts(parts, "0.04");
    sph::StateHeader headerA, headerB;
    const auto a = sph::readParticleFile<2>(whole / "0.04/fluid.vtu", "a", headerA);
    const auto b = sph::readParticleFile<2>(parts / "0.04/fluid.vtu", "b", headerB);
    // The runs sorted by cell at different steps: match particles by id.
    std::map<std::int64_t, sph::Vec<2>> positionOf;
    for (std::size_t i = 0; i < b.size(); ++i) positionOf[b.globalId[i]] = b.position[i];
    double largest = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, (a.position[i] - positionOf.at(a.globalId[i])).norm());
    EXPECT_GT(largest, 0.0);  // not bit for bit: the controller restarted
    // Relative tolerance times the column's width (0.057 m); measured 1.1e-8.
    EXPECT_LT(largest, 1e-6 * 0.057) << "largest position difference";
}

namespace {

// Every time the .pvd lists, with both its files complete and readable; returns the times.
std::vector<double> checkCollection(const std::filesystem::path& dir) {
    const std::string collection = readText(dir / (dir.filename().string() + ".pvd"));
    const std::regex dataSet("<DataSet timestep=\"([^\"]+)\" group=\"\" part=\"([01])\" file=\"([^\"]+)\"/>");
    std::vector<double> times;
    for (auto it = std::sregex_iterator(collection.begin(), collection.end(), dataSet); it != std::sregex_iterator(); ++it) {
        sph::StateHeader header;
        EXPECT_NO_THROW(sph::readParticleFile<2>(dir / (*it)[3].str(), "part", header)) << (*it)[3];
        if ((*it)[2] == "0") times.push_back(std::stod((*it)[1]));
    }
    return times;
}

// The dam break at dx = a/20 (800 fluid particles) to 0.1 s, about 2 s of wall time.
std::filesystem::path mediumDamBreak(const std::string& variant) {
    const auto dir = copyCase("damBreak2D", variant);
    setEntry(dir / "system/generateParticlesDict", "spacing", "0.0028575");
    setEntry(dir / "system/controlDict", "endTime", "0.1");
    sph::generateParticles(dir, false);
    return dir;
}

}  // namespace

TEST(Restart, StopSignalWritesTheStateAndTheRestartContinuesExactly) {
    const auto reference = mediumDamBreak("reference");
    sph::runCase(reference);
    for (const int signal : {SIGTERM, SIGINT}) {
        const auto dir = mediumDamBreak(signal == SIGTERM ? "term" : "int");
        const pid_t solver = startSolver(dir);
        // Mid-run: after the first write, between steps or in one.
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (!std::filesystem::exists(dir / "0.01") && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        std::this_thread::sleep_for(std::chrono::milliseconds(137));
        kill(solver, signal);
        const int status = waitForExit(solver);
        ASSERT_TRUE(WIFEXITED(status)) << readText(dir / "log");
        EXPECT_EQ(WEXITSTATUS(status), 0) << readText(dir / "log");
        const std::string log = readText(dir / "log");
        EXPECT_NE(log.find(signal == SIGTERM ? "SIGTERM received: stopped at step" : "SIGINT received: stopped at step"), std::string::npos) << log;
        const std::vector<double> written = checkCollection(dir);
        ASSERT_FALSE(written.empty());
        EXPECT_GT(written.back(), 0.01);
        EXPECT_LT(written.back(), 0.1);
        sph::runCase(dir);
        expectSameState(reference / "0.1", dir / "0.1");
    }
}

TEST(Restart, KillAtRandomMomentsLosesNothingWritten) {
    // kill -9 at random moments; after each, every listed time is complete, and the restarts
    // together end in the uninterrupted run's state. Every other kill comes as soon as a write's
    // temporary appears (inside a write), the others 0-40 ms after the run has listed one more
    // time (in a step or a write): kills after fixed delays depended on the machine's speed (a
    // run of 0.6 s finished after two).
    const auto reference = mediumDamBreak("reference");
    sph::runCase(reference);
    const auto dir = mediumDamBreak("killed");
    const auto listedTimes = [&] {
        const std::string collection = readText(dir / (dir.filename().string() + ".pvd"));
        std::size_t count = 0;
        for (auto at = collection.find("part=\"0\""); at != std::string::npos; at = collection.find("part=\"0\"", at + 1)) ++count;
        return count;
    };
    std::mt19937 random(20261122);
    std::uniform_int_distribution<int> milliseconds(0, 40);
    int kills = 0;
    // The hidden temporaries a write makes, named after its process (a killed run's stay until the next run starts).
    const auto temporaries = [&] {
        std::set<std::string> names;
        for (const auto& item : std::filesystem::directory_iterator(dir))
            if (item.path().filename().string()[0] == '.') names.insert(item.path().filename().string());
        return names;
    };
    int killsInAWrite = 0;
    for (int attempt = 0; attempt < 12; ++attempt) {
        const std::size_t listed = listedTimes();
        const std::set<std::string> before = temporaries();
        const auto writing = [&] { return std::ranges::any_of(temporaries(), [&](const std::string& name) { return !before.contains(name); }); };
        const pid_t solver = startSolver(dir);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        const bool inAWrite = attempt % 2 == 0;
        while (listedTimes() <= listed && !(inAWrite && writing()) && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        if (!inAWrite) std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds(random)));
        kill(solver, SIGKILL);
        const int status = waitForExit(solver);
        if (WIFEXITED(status)) break;  // it finished first
        ASSERT_TRUE(WIFSIGNALED(status));
        ++kills;
        if (writing()) ++killsInAWrite;  // its temporaries left behind
        checkCollection(dir);
    }
    // A kill may land after the end time was written, while the solver exits: nothing left to run.
    if (!std::filesystem::exists(dir / "0.1")) {
        const int status = waitForExit(startSolver(dir));
        ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readText(dir / "log");
    }
    EXPECT_GE(kills, 3);
    EXPECT_GE(killsInAWrite, 1);
    const std::vector<double> written = checkCollection(dir);
    EXPECT_EQ(written.size(), 11u);  // 0, 0.01, ..., 0.1: each once
    expectSameState(reference / "0.1", dir / "0.1");
    for (const auto& item : std::filesystem::directory_iterator(dir))
        EXPECT_NE(item.path().filename().string()[0], '.') << "left behind: " << item.path();
    std::cout << kills << " kills, " << killsInAWrite << " inside a write\n";
}
