// A running case under the conditions of a shared machine: its controlDict edited while it
// runs, the disk filling up, an unwritable case directory. Each runs wcsph as a process.
#include "driver/RunControls.hpp"
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
    // endTime 0.2 with writeInterval 0.005 ends the run there with writes every 0.005. The good
    // edit waits for the bad one's report (a fixed pause let a fast machine run past the new
    // endTime before it was read).
    const auto dir = damBreak("5");
    const std::string controlDict = readText(dir / "system/controlDict");
    const pid_t solver = startSolver(dir);
    waitUntilExists(dir / "0.01");
    writeFile(dir / "system/controlDict", std::regex_replace(controlDict, std::regex("endTime +5;"), "endTime -1;"));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (readText(dir / "log").find("endTime -1 is not later than the current time") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::string edited = std::regex_replace(controlDict, std::regex("endTime +5;"), "endTime 0.2;");
    writeFile(dir / "system/controlDict", std::regex_replace(edited, std::regex("writeInterval +0.01;"), "writeInterval 0.005;"));
    const int status = waitForExit(solver);
    const std::string log = readText(dir / "log");
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
    EXPECT_NE(log.find("warning: ignoring the changed"), std::string::npos) << log;
    EXPECT_NE(log.find("endTime 0.2, writeInterval 0.005"), std::string::npos) << log;
    EXPECT_NE(log.find("End at t = 0.2:"), std::string::npos) << log;
    EXPECT_TRUE(std::filesystem::exists(dir / "0.195/fluid.vtu"));
    EXPECT_TRUE(std::filesystem::exists(dir / "0.2/fluid.vtu"));
    EXPECT_FALSE(std::filesystem::exists(dir / "0.205"));
}

TEST(RunControl, AnEditFinishedWithinTheClocksTickIsRead) {
    // An editor truncates the file and writes it again; read in between (a warning: endTime
    // missing), the finished edit can carry the same modification time. Its size tells.
    const auto dir = freshDirectory();
    const auto file = dir / "controlDict";
    writeFile(file, "endTime 5; writeInterval 0.01;\n");
    sph::ControlDictWatcher watcher(file, true);
    const sph::RunControls current{5.0, 0.01};
    const auto before = std::filesystem::last_write_time(file);
    writeFile(file, "writeInterval 0.01;\n");  // the half-written state
    std::filesystem::last_write_time(file, before + std::chrono::milliseconds(1));
    EXPECT_FALSE(watcher.changed(current, 0.1));  // read half-written: reported and ignored
    writeFile(file, "endTime 0.2; writeInterval 0.005;\n");
    std::filesystem::last_write_time(file, before + std::chrono::milliseconds(1));
    const auto controls = watcher.changed(current, 0.1);
    ASSERT_TRUE(controls);
    EXPECT_DOUBLE_EQ(controls->endTime, 0.2);
    EXPECT_DOUBLE_EQ(controls->writeInterval, 0.005);
    EXPECT_FALSE(watcher.changed(current, 0.1));  // read once
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
    std::vector<std::string> expected{
        "0",     "constant", dir.filename().string() + ".pvd", "log", "koshizukaOka1996Front.csv", "martinMoyce1952Front.csv", "postProcessing",
        "system"};
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
    EXPECT_NE(log.find("error: cannot open dictionary '" + (dir / "system/sphSchemes").string() + "': permission denied or unreadable"),
              std::string::npos)
        << log;
}

TEST(RunControl, TheLogEndsWithTheError) {
    // `wcsph > log` and `wcsph | tee log`: the error went to stderr only, or landed in the log
    // above the output printed before it. Now stdout, a file of its own, ends with it too.
    const auto dir = damBreak("0.02");
    replaceInFile(dir / "system/timeIntegration", "courant     0.2;", "courant     10;");
    const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
    std::string executable = SPHKIT_WCSPH_EXECUTABLE, caseOption = "-case", caseDirectory = dir.string();
    char* argv[] = {executable.data(), caseOption.data(), caseDirectory.data(), nullptr};
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666), STDOUT_FILENO);
        dup2(open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666), STDERR_FILENO);
        execv(executable.c_str(), argv);
        _exit(127);
    }
    const int status = waitForExit(pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
    const std::string log = readText(dir / "stdout"), errors = readText(dir / "stderr");
    const std::string message = "keyword 'courant' in dictionary 'timeIntegration': must not exceed 1";
    EXPECT_NE(errors.find(message), std::string::npos) << errors;
    ASSERT_NE(log.find("Selecting"), std::string::npos) << log;
    const std::size_t at = log.rfind(message);
    ASSERT_NE(at, std::string::npos) << log;
    EXPECT_GT(at, log.rfind("Selecting"));
    EXPECT_EQ(log.find('\n', at), log.size() - 1) << log;  // the error's line is the last
}

TEST(RunControl, OnlyTheTemporariesOfEndedRunsAreRemoved) {
    // The solver removed every `.<x>.tmp<digits>`, the user's own too, and a running solver's.
    const auto dir = damBreak("0.01");
    const pid_t ended = fork();
    if (ended == 0) _exit(0);
    waitForExit(ended);
    const std::string gone = std::to_string(ended);
    for (const std::string& name : std::vector<std::string>{".0.005.tmp" + gone, ".fluid.pvd.tmp" + gone, ".notes.tmp" + gone, ".0.005.tmp1"})
        std::filesystem::create_directories(dir / name);
    const int status = waitForExit(startSolver(dir));
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readText(dir / "log");
    EXPECT_FALSE(std::filesystem::exists(dir / (".0.005.tmp" + gone)));  // a killed run's time directory
    EXPECT_FALSE(std::filesystem::exists(dir / (".fluid.pvd.tmp" + gone)));
    EXPECT_TRUE(std::filesystem::exists(dir / (".notes.tmp" + gone)));  // not a name sphkit writes
    EXPECT_TRUE(std::filesystem::exists(dir / ".0.005.tmp1"));          // process 1 still runs
}

TEST(RunControl, ACaseNameOf250Characters) {
    // The .pvd's temporary name passed the 255 bytes a file name may have on c09449c.
    const auto source = damBreak("0.01");
    const auto dir = source.parent_path() / std::string(250, 'c');
    std::filesystem::remove_all(dir);
    std::filesystem::rename(source, dir);
    const int status = waitForExit(startSolver(dir));
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readText(dir / "log");
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(250, 'c') + ".pvd")));
    std::filesystem::remove_all(dir);
}
