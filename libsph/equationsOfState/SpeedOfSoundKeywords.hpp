// The keywords every equation of state documents around its own: the speed of sound, given or
// derived (physics/FluidProperties resolves it before the factory runs), and the background
// pressure.
#pragma once

#include "core/Registry.hpp"

#include <vector>

namespace sph {

inline std::vector<CoefficientDoc> withSpeedOfSound(std::vector<CoefficientDoc> own) {
    std::vector<CoefficientDoc> all{{"c0", "", "speed of sound [m/s] (this or c0FromHeight)"},
                                    {"c0FromHeight", "", "{ coefficient 10; height H; }: c0 = coefficient sqrt(|g| H) (this or c0)"}};
    all.insert(all.end(), own.begin(), own.end());
    all.push_back({"backgroundPressure", "0", "p0 added to the pressure [Pa]"});
    return all;
}

}  // namespace sph
