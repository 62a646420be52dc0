// Particle fields as CSV (one row per particle: id, position, then every written field, vectors
// as one column per component), for plotting scripts that have no VTK reader.
#pragma once

#include "core/ParticleSet.hpp"

#include <filesystem>

namespace sph {

template <int D>
void writeParticleCsv(const std::filesystem::path& file, const ParticleSet<D>& particles);

}  // namespace sph
