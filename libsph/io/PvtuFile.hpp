// The index of a particle state written in pieces, one .vtu per rank (a parallel run): a
// PUnstructuredGrid .pvtu naming the pieces and the point arrays they share, so that ParaView
// opens the pieces as one data set, and a reader (a restart on any number of ranks) finds them.
//   <VTKFile type="PUnstructuredGrid" ...><PUnstructuredGrid GhostLevel="0">
//     <PPointData> <PDataArray type="Int64" Name="id"/> ... </PPointData>
//     <PPoints> <PDataArray type="Float64" NumberOfComponents="3"/> </PPoints>
//     <Piece Source="fluid_0.vtu"/> <Piece Source="fluid_1.vtu"/> ...
#pragma once

#include "core/ParticleSet.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sph {

struct PointArray {
    std::string name;
    std::string type;  // Int64, Int32 or Float64
    int components;
    bool operator==(const PointArray&) const = default;
};

// The point arrays writeParticleFile writes for the set, in its order.
template <int D>
std::vector<PointArray> writtenPointArrays(const ParticleSet<D>& particles);

// Writes the index atomically; pieces are named relative to its directory.
void writePvtu(const std::filesystem::path& file, const std::vector<PointArray>& arrays, const std::vector<std::string>& pieces);

// The pieces an index names, as paths beside it: FatalError naming the file where it is missing,
// names no piece, or names a piece that is not there.
std::vector<std::filesystem::path> readPvtuPieces(const std::filesystem::path& file);

}  // namespace sph
