// The particle-shifting family: after every step, fluid particles move by dt times a shifting
// velocity that evens out their spacing (physics/ParticleShiftingPass.tpp), their velocity
// unchanged and, with continuity density, their density by the shift's Taylor term (the
// renormalised density gradient). Optional: a case without `particleShifting` in
// system/sphSchemes shifts nothing and pays nothing.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "particleShifting/FickianShiftingLind2012.hpp"
#include "particleShifting/FreeSurfaceMarrone2010.hpp"
#include "particleShifting/ShiftingSun2017.hpp"
#include "physics/ModelContext.hpp"

#include <string>
#include <variant>

namespace sph {

struct NoShifting {
    static constexpr bool enabled = false;
};

struct ParticleShifting {
    std::variant<NoShifting, FickianShiftingLind2012, ShiftingSun2017> law;
    FreeSurfaceMarrone2010 surface;
    double dx = 0.0;  // W(dx) scales the anti-clumping term

    bool enabled() const { return !std::holds_alternative<NoShifting>(law); }
    // The law's pair weight (none: every pair counts once).
    TensileShiftingWeight pairWeight() const {
        return std::visit(
            [](const auto& l) {
                if constexpr (std::decay_t<decltype(l)>::enabled)
                    return l.pairWeight();
                else
                    return TensileShiftingWeight{};
            },
            law);
    }
};

using ParticleShiftingRegistry = Registry<ParticleShifting, const Dictionary&, const ModelContext&>;

ParticleShiftingRegistry makeParticleShiftingRegistry();

std::string describe(const ParticleShifting& shifting);

}  // namespace sph
