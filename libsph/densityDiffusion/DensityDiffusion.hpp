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

#include <string>
#include <variant>

namespace sph {

template <int D>
using DensityDiffusion = std::variant<NoDensityDiffusion, MolteniColagrossi2009, Fourtakas2019<D>, Antuono2010>;

template <int D>
using DensityDiffusionRegistry = Registry<DensityDiffusion<D>, const Dictionary&, const ModelContext&>;

template <int D>
DensityDiffusionRegistry<D> makeDensityDiffusionRegistry();

template <int D>
std::string describe(const DensityDiffusion<D>& diffusion) {
    return describeModel(diffusion);
}

}  // namespace sph
