// The keyword every density diffusion reads: its coefficient delta, documented and defaulted here once.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"

namespace sph {

inline CoefficientDoc diffusionCoefficientDoc() { return {"delta", "0.1", "diffusion coefficient"}; }
inline double readDiffusionCoefficient(const Dictionary& dict) { return dict.getNonNegativeOrDefault("delta", 0.1); }

}  // namespace sph
