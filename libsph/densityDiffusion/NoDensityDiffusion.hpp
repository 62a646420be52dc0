// No density diffusion term.
// Example (system/sphSchemes):   densityDiffusion { type none; }
#pragma once

namespace sph {

struct NoDensityDiffusion {
    static constexpr bool enabled = false;
};

}  // namespace sph
