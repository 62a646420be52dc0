// The error handling every executable shares: a FatalError is the user's to fix and prints
// its message (exit 1); anything else is an internal error (exit 3).
#pragma once

#include "core/FatalError.hpp"

#include <fmt/format.h>

#include <exception>

namespace sph {

template <class Body>
int exitCodeOf(Body&& body) {
    try {
        body();
    } catch (const FatalError& e) {
        fmt::print(stderr, "\n{}\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "\nerror: internal error: {}\n", e.what());
        return 3;
    }
    return 0;
}

}  // namespace sph
