// Names of time directories, as OpenFOAM writes them: the shortest form of the time at
// 8 significant digits ("0", "0.05", "1.25e-05").
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string>

namespace sph {

// A time that 8 digits do not name to 1e-12 (a state written on a stop signal) gets as
// many digits as it needs, so two written times never share a directory.
inline std::string timeName(double t) {
    for (int digits = 8; digits < 17; ++digits) {
        std::string name = fmt::format("{:.{}g}", t, digits);
        if (std::abs(std::strtod(name.c_str(), nullptr) - t) <= 1e-12 * std::abs(t)) return name;
    }
    return fmt::format("{:.17g}", t);
}

}  // namespace sph
