// A running case under the conditions of a shared machine: its controlDict edited while it
// runs, the disk filling up, an unwritable case directory. Each runs wcsph as a process.
#include "generation/ParticleGenerator.hpp"
#include "support/CaseFixture.hpp"
#include "support/SolverProcess.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <sys/resource.h>
#include <thread>

using namespace sph::test;

namespace {

// The dam break at dx = a/20 (800 fluid particles): about 20 ms of wall time per 0.001 s.
std::filesystem::path damBreak(const std::string& endTime) {
    const auto dir = copyCase("damBreak2D");
    setEntry(dir / "system/generateParticlesDict", "spacing", "0.0028575");
    setEntry(dir / "system/controlDict", "endTime", endTime);
    sph::generateParticles(dir, false);
    return dir;
}

void waitUntilExists(const std::filesystem::path& path) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!std::filesystem::exists(path) && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

std::vector<std::string> entries(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& item : std::filesystem::directory_iterator(dir)) names.push_back(item.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(RunControl, ControlDictEditsTakeEffectWhileRunning) {
    // endTime 5 s would take minutes; once running, a bad edit is reported and ignored, then
    // endTime 0.03 with writeInterval 0.005 ends the run there with writes every 0.005.
    const auto dir = damBreak("5");
    const std::string controlDict = readText(dir / "system/controlDict");
    const pid_t solver = startSolver(dir);
    waitUntilExists(dir / "0.01");
    writeFile(dir / "system/controlDict", std::regex_replace(controlDict, std::regex("endTime +5;"), "endTime -1;"));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::string edited = std::regex_replace(controlDict, std::regex("endTime +5;"), "endTime 0.03;");
    writeFile(dir / "system/controlDict", std::regex_replace(edited, std::regex("writeInterval +0.01;"), "writeInterval 0.005;"));
    const int status = waitForExit(solver);
    const std::string log = readText(dir / "log");
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
    EXPECT_NE(log.find("warning: ignoring the changed"), std::string::npos) << log;
    EXPECT_NE(log.find("endTime -1 is not later than the current time"), std::string::npos) << log;
    EXPECT_NE(log.find("endTime 0.03, writeInterval 0.005"), std::string::npos) << log;
    EXPECT_NE(log.find("End at t = 0.03:"), std::string::npos) << log;
    EXPECT_TRUE(std::filesystem::exists(dir / "0.025/fluid.vtu"));
    EXPECT_TRUE(std::filesystem::exists(dir / "0.03/fluid.vtu"));
    EXPECT_FALSE(std::filesystem::exists(dir / "0.035"));
}

TEST(RunControl, RunTimeModifiableOffIgnoresEdits) {
    const auto dir = damBreak("0.03");
    std::ofstream(dir / "system/controlDict", std::ios::app) << "runTimeModifiable no;\n";
    const std::string controlDict = readText(dir / "system/controlDict");
    const pid_t solver = startSolver(dir);
    waitUntilExists(dir / "0.01");
    writeFile(dir / "system/controlDict", std::regex_replace(controlDict, std::regex("endTime +0.03;"), "endTime 0.02;"));
    const int status = waitForExit(solver);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readText(dir / "log");
    EXPECT_TRUE(std::filesystem::exists(dir / "0.03/fluid.vtu")) << readText(dir / "log");
}

TEST(RunControl, DiskFullStopsWithAClearErrorAndKeepsWhatWasWritten) {
    // A file size limit of 40 kB stands in for a full disk: the first state (about 100 kB)
    // cannot be written. The run stops naming the file; no partial time directory or
    // temporary is left, the collection lists time 0 only, and the case restarts from it.
    const auto dir = damBreak("0.02");
    const pid_t solver = startSolver(dir, [] {
        signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG
        const rlimit limit{40000, 40000};
        setrlimit(RLIMIT_FSIZE, &limit);
    });
    const int status = waitForExit(solver);
    const std::string log = readText(dir / "log");
    ASSERT_TRUE(WIFEXITED(status)) << log;
    EXPECT_EQ(WEXITSTATUS(status), 1) << log;
    EXPECT_NE(log.find("error: cannot write particle file"), std::string::npos) << log;
    EXPECT_NE(log.find("while writing '" + (dir / "0.01").string() + "'"), std::string::npos) << log;
    std::vector<std::string> expected{"0", "constant", dir.filename().string() + ".pvd", "log", "martinMoyce1952Front.csv", "postProcessing", "system"};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(entries(dir), expected);
    EXPECT_EQ(readText(dir / (dir.filename().string() + ".pvd")).find("0.01"), std::string::npos);
    const int rerun = waitForExit(startSolver(dir));
    EXPECT_TRUE(WIFEXITED(rerun) && WEXITSTATUS(rerun) == 0) << readText(dir / "log");
    EXPECT_TRUE(std::filesystem::exists(dir / "0.02/walls.vtu"));
}

namespace {

// Runs wcsph as the unprivileged user 'nobody' (root reads and writes anywhere) and returns
// its log after checking it failed with exit status 1.
std::string failureAsNobody(const std::filesystem::path& dir) {
    const pid_t solver = startSolver(dir, [] {
        if (geteuid() == 0) {
            setgid(65534);
            setuid(65534);
        }
    });
    const int status = waitForExit(solver);
    const std::string log = readText(dir / "log");
    EXPECT_TRUE(WIFEXITED(status)) << log;
    EXPECT_EQ(WEXITSTATUS(status), 1) << log;
    EXPECT_EQ(log.find("Starting time loop"), std::string::npos) << log;
    return log;
}

}  // namespace

TEST(RunControl, UnwritableCaseDirectoryStopsBeforeTheFirstStep) {
    const auto dir = damBreak("0.02");
    namespace fs = std::filesystem;
    fs::permissions(dir, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write, fs::perm_options::remove);
    const std::string log = failureAsNobody(dir);
    fs::permissions(dir, fs::perms::owner_write, fs::perm_options::add);
    EXPECT_NE(log.find("directory not writable"), std::string::npos) << log;
}

TEST(RunControl, UnreadableDictionaryIsAClearError) {
    const auto dir = damBreak("0.02");
    std::filesystem::permissions(dir / "system/sphSchemes", std::filesystem::perms::none);
    const std::string log = failureAsNobody(dir);
    EXPECT_NE(log.find("error: cannot open dictionary '" + (dir / "system/sphSchemes").string() + "': permission denied or unreadable"), std::string::npos)
        << log;
}
