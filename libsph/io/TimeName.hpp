// Names of time directories, as OpenFOAM writes them: the shortest form of the time at
// 8 significant digits ("0", "0.05", "1.25e-05").
#pragma once

#include <fmt/format.h>

#include <string>

namespace sph {

inline std::string timeName(double t) { return fmt::format("{:.8g}", t); }

}  // namespace sph
