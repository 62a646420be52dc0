// wcsph run as a separate process, for the tests that signal, kill or restrict it.
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace sph::test {

// Starts wcsph on `dir`, its output appended to dir/log. `inChild` runs in the child before
// the solver starts (set a resource limit, drop privileges): async-signal-safe calls only.
template <class ChildSetup>
pid_t startSolver(const std::filesystem::path& dir, ChildSetup inChild) {
    const std::string log = (dir / "log").string();
    std::string executable = SPHKIT_WCSPH_EXECUTABLE, caseOption = "-case", caseDirectory = dir.string();
    char* argv[] = {executable.data(), caseOption.data(), caseDirectory.data(), nullptr};
    const pid_t pid = fork();
    if (pid == 0) {
        const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0666);
        dup2(out, STDOUT_FILENO);
        dup2(out, STDERR_FILENO);
        inChild();
        execv(executable.c_str(), argv);
        _exit(127);
    }
    EXPECT_GT(pid, 0) << "cannot start " << executable;
    return pid;
}

inline pid_t startSolver(const std::filesystem::path& dir) {
    return startSolver(dir, [] {});
}

// The wait status of a child (WIFEXITED, WEXITSTATUS, WIFSIGNALED apply).
inline int waitForExit(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return status;
}

inline std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace sph::test
