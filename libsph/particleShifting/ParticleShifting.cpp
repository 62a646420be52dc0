#include "particleShifting/ParticleShifting.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

namespace {

FreeSurfaceMarrone2010 readFreeSurface(const Dictionary& dict) {
    FreeSurfaceMarrone2010 surface;
    surface.surfaceLambda = dict.getPositiveOrDefault("surfaceLambda", surface.surfaceLambda);
    surface.splashLambda = dict.getNonNegativeOrDefault("splashLambda", surface.splashLambda);
    if (surface.surfaceLambda > 1.0)
        dict.fail("surfaceLambda", fmt::format("lambda is 1 in a full support: a threshold above it marks every particle as free surface; found {:g} "
                                               "(valid: 0 < surfaceLambda <= 1, 0.55 as Sun et al. 2017)",
                                               surface.surfaceLambda));
    if (surface.splashLambda > surface.surfaceLambda)
        dict.fail("splashLambda", fmt::format("must not exceed surfaceLambda ({:g}), found {:g}", surface.surfaceLambda, surface.splashLambda));
    return surface;
}

const std::vector<CoefficientDoc> freeSurfaceDocs{
    {"surfaceLambda", "0.55", "free surface below it (smallest eigenvalue of the moment matrix, Marrone et al. 2010)"},
    {"splashLambda", "0.4", "no shift below it (too few neighbours)"}};

}  // namespace

ParticleShiftingRegistry makeParticleShiftingRegistry() {
    ParticleShiftingRegistry registry("particleShifting");
    registry.add("none", {"no shifting", "", {}}, [](const Dictionary&, const ModelContext& c) { return ParticleShifting{NoShifting{}, {}, c.dx}; });
    std::vector<CoefficientDoc> lindDocs{{"coefficient", "2", "A of delta u = -A h |v| grad C"}};
    lindDocs.insert(lindDocs.end(), freeSurfaceDocs.begin(), freeSurfaceDocs.end());
    registry.add(
        "lind",
        {"Fickian shifting down the concentration gradient, scaled by the particle's speed",
         "Lind et al., J. Comput. Phys. 231 (2012) 1499; Skillen et al., CMAME 265 (2013) 163", lindDocs},
        [](const Dictionary& dict, const ModelContext& c) {
            return ParticleShifting{FickianShiftingLind2012(dict.getPositiveOrDefault("coefficient", 2.0), c.h), readFreeSurface(dict), c.dx};
        });
    std::vector<CoefficientDoc> sunDocs{{"R", "0.2", "anti-clumping weight"}, {"n", "4", "anti-clumping exponent (integer)"}};
    sunDocs.insert(sunDocs.end(), freeSurfaceDocs.begin(), freeSurfaceDocs.end());
    registry.add(
        "sun",
        {"the particle shifting technique of delta+-SPH, scaled by the largest fluid speed",
         "Sun et al., Comput. Phys. Commun. 215 (2017) 179; CMAME 348 (2019) 912", sunDocs},
        [](const Dictionary& dict, const ModelContext& c) {
            const double n = dict.getPositiveOrDefault("n", 4.0);
            if (n != std::floor(n) || n > 16.0)
                dict.fail("n", fmt::format("the anti-clumping exponent is a whole power, found {:g} (valid: 1 to 16; 4 as Sun et al.)", n));
            return ParticleShifting{ShiftingSun2017(dict.getNonNegativeOrDefault("R", 0.2), static_cast<int>(n), c.h), readFreeSurface(dict), c.dx};
        });
    return registry;
}

std::string describe(const ParticleShifting& shifting) {
    const std::string surface = fmt::format("surfaceLambda {:g}, splashLambda {:g}", shifting.surface.surfaceLambda, shifting.surface.splashLambda);
    return std::visit(
        [&](const auto& law) -> std::string {
            using T = std::decay_t<decltype(law)>;
            if constexpr (std::is_same_v<T, NoShifting>)
                return "none";
            else if constexpr (std::is_same_v<T, FickianShiftingLind2012>)
                return fmt::format("lind: coefficient {:g}, {}", law.coefficient, surface);
            else
                return fmt::format("sun: R {:g}, n {}, {}", law.R, law.n, surface);
        },
        shifting.law);
}

}  // namespace sph
