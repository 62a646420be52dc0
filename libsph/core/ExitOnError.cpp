#include "core/ExitOnError.hpp"

#include <sys/stat.h>
#include <unistd.h>

namespace sph {

std::string describeFilesystemError(const std::filesystem::filesystem_error& e) {
    std::string operation = e.what();
    if (const std::string prefix = "filesystem error: "; operation.starts_with(prefix)) operation.erase(0, prefix.size());
    if (const std::size_t cause = operation.find(": " + e.code().message()); cause != std::string::npos) operation.erase(cause);
    std::string text = operation;
    if (!e.path1().empty()) text += " '" + e.path1().string() + "'";
    if (!e.path2().empty()) text += " to '" + e.path2().string() + "'";
    return text + ": " + e.code().message();
}

namespace {

bool stdoutIsItsOwnFile() {
    struct stat out {
    }, err{};
    if (::isatty(STDOUT_FILENO) || ::fstat(STDOUT_FILENO, &out) != 0) return false;
    return ::fstat(STDERR_FILENO, &err) != 0 || out.st_dev != err.st_dev || out.st_ino != err.st_ino;
}

}  // namespace

void reportError(const std::string& message) {
    std::fflush(stdout);
    if (stdoutIsItsOwnFile()) {
        fmt::print(stdout, "\n{}\n", message);
        std::fflush(stdout);
    }
    fmt::print(stderr, "\n{}\n", message);
}

}  // namespace sph
