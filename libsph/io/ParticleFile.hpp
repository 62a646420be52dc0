// Particle state files: VTK XML unstructured grids (.vtu, appended binary, zlib-compressed),
// one vertex cell per particle, so ParaView opens them as they are and the solver restarts
// from them exactly (every field is Float64). Point data: one array per written field,
// 3-component arrays for vectors (zero-padded below 3D), "id" for global ids. Field data:
// TimeValue, step, dimension, spacing, domainMin, domainMax, periodic (when any direction is),
// for walls patchNames and patchLayers (the layers the fluid finds behind each patch's faces,
// as generateParticles laid them), and for a state the solver wrote, "integrator" (the type that wrote it)
// and "restart:<key>" arrays: what the integrator and free bodies carry from step to step
// besides particle fields, so a restart continues the run exactly.
// Files are written to a temporary name in the same directory and renamed, so a reader never
// sees a half-written file.
#pragma once

#include "core/ParticleSet.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sph {

struct StateHeader {
    int dimension = 0;
    double time = 0.0;
    long step = 0;
    double spacing = 0.0;
    std::vector<double> domainMin, domainMax;
    std::vector<double> periodic;  // 1 per periodic direction, 0 otherwise; empty: none
    std::vector<std::string> patchNames;
    std::vector<double> patchLayers;  // per patch; empty (a file from before it): count the wall field `layer`
    std::string integrator;
    std::map<std::string, std::vector<double>> restart;
};

// The places of the particles a file holds, in order; none: the set's owned particles (halo
// copies are in other ranks' files). A decomposed run names its owned ones among its copies
// rather than copying them into a set of their own.
using WrittenPlaces = std::optional<std::span<const std::uint32_t>>;

template <int D>
void writeParticleFile(const std::filesystem::path& file, const ParticleSet<D>& particles, const StateHeader& header,
                       WrittenPlaces places = std::nullopt);

// Reads a particle file; FatalError naming the file for a missing, unreadable or incomplete one.
template <int D>
ParticleSet<D> readParticleFile(const std::filesystem::path& file, const std::string& setName, StateHeader& header);

// The header alone (to pick the dimension before reading).
StateHeader readParticleFileHeader(const std::filesystem::path& file);

}  // namespace sph
