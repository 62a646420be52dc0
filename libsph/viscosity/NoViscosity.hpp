// Inviscid: no viscous term. The force loop drops it at compile time.
// Example (system/sphSchemes):   viscosity { type none; }
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"

#include <string>
#include <string_view>

namespace sph {

struct NoViscosity {
    static constexpr std::string_view name = "none";
    static ModelDoc documentation() { return {"inviscid", "", {}}; }
    static NoViscosity create(const Dictionary&, const ModelContext&) { return {}; }
    std::string describe() const { return "none"; }

    static constexpr bool enabled = false;
};

}  // namespace sph
