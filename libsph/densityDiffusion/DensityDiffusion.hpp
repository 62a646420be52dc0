// The density-diffusion family (acts with continuity density only): each model declares itself
// in its header (name, documentation, factory, run-log line) and is one entry in the variant.
#pragma once

#include "core/Registry.hpp"
#include "densityDiffusion/Antuono2010.hpp"
#include "densityDiffusion/Fourtakas2019.hpp"
#include "densityDiffusion/MolteniColagrossi2009.hpp"
#include "densityDiffusion/NoDensityDiffusion.hpp"
#include "io/Dictionary.hpp"
#include "physics/ModelContext.hpp"

#include <concepts>
#include <string>
#include <variant>

namespace sph {

template <int D>
using DensityDiffusion = std::variant<NoDensityDiffusion, MolteniColagrossi2009, Fourtakas2019<D>, Antuono2010>;

// What the pair loop asks of a density diffusion: whether it has a term at all (a case without
// one compiles none), and if so the rates a pair adds to i and j from six numbers: g.r_ij, r^2,
// 1/(r^2 + 0.01 h^2), rho_i, rho_j, F; or, where usesDensityGradient, r^2, 1/(r^2 + 0.01 h^2),
// rho_i, rho_j, F and (grad rho_i + grad rho_j).r_ij.
template <class M>
concept DensityDiffusionModel = requires {
    { M::enabled } -> std::convertible_to<bool>;
}
&&(!M::enabled || requires(const M diffusion, double value, double& rate) {
    { diffusion.pairRates(value, value, value, value, value, value, rate, rate) } -> std::same_as<void>;
});
template <class Family>
inline constexpr bool allDensityDiffusions = false;
template <class... Models>
inline constexpr bool allDensityDiffusions<std::variant<Models...>> = (DensityDiffusionModel<Models> && ...);
static_assert(allDensityDiffusions<DensityDiffusion<1>> && allDensityDiffusions<DensityDiffusion<2>> && allDensityDiffusions<DensityDiffusion<3>>);

template <int D>
using DensityDiffusionRegistry = Registry<DensityDiffusion<D>, const Dictionary&, const ModelContext&>;

template <int D>
DensityDiffusionRegistry<D> makeDensityDiffusionRegistry();

template <int D>
std::string describe(const DensityDiffusion<D>& diffusion) {
    return describeModel(diffusion);
}

}  // namespace sph
