// The error handling every executable shares: a FatalError is the user's to fix and prints
// its message (exit 1), as does a filesystem error (the path and the cause); anything else is
// an internal error (exit 3). The message goes to stderr and, when stdout is a file or a pipe
// of its own (`wcsph > log`, `wcsph | tee log`), to stdout as well, after everything printed
// before it: a log ends with the error that ended the run.
#pragma once

#include "core/FatalError.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

namespace sph {

// "cannot create directory '<path>': Permission denied" from the standard library's
// "filesystem error: cannot create directory: Permission denied [<path>]".
std::string describeFilesystemError(const std::filesystem::filesystem_error& e);

// Writes `message` where the user and the log see it (see above).
void reportError(const std::string& message);

template <class Body>
int exitCodeOf(Body&& body) {
    try {
        body();
    } catch (const FatalError& e) {
        reportError(e.what());
        return 1;
    } catch (const std::filesystem::filesystem_error& e) {
        reportError("error: " + describeFilesystemError(e));
        return 1;
    } catch (const std::exception& e) {
        reportError(std::string("error: internal error: ") + e.what());
        return 3;
    }
    return 0;
}

}  // namespace sph
