// Inviscid: no viscous term. The force loop drops it at compile time.
// Example (system/sphSchemes):   viscosity { type none; }
#pragma once

namespace sph {

struct NoViscosity {
    static constexpr bool enabled = false;
};

}  // namespace sph
