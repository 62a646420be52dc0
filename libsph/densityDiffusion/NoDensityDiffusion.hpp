// No density diffusion term.
// Example (system/sphSchemes):   densityDiffusion { type none; }
#pragma once

#include "densityDiffusion/DiffusionCoefficient.hpp"
#include "physics/ModelContext.hpp"

#include <string>
#include <string_view>

namespace sph {

struct NoDensityDiffusion {
    static constexpr std::string_view name = "none";
    static ModelDoc documentation() { return {"no density diffusion", "", {}}; }
    static NoDensityDiffusion create(const Dictionary&, const ModelContext&) { return {}; }
    std::string describe() const { return "none"; }

    static constexpr bool enabled = false;
};

}  // namespace sph
