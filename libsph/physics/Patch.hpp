// A wall patch: its range of the wall particle set, its boundary model and its motion.
#pragma once

#include "boundaryModels/BoundaryModel.hpp"
#include "motion/PatchMotion.hpp"
#include "neighbourSearch/CellLinkedList.hpp"

#include <memory>
#include <optional>
#include <string>

namespace sph {

template <int D>
struct Patch {
    std::string name;
    std::size_t begin = 0, end = 0;  // range in the wall particle set
    std::unique_ptr<BoundaryModel<D>> model;
    std::optional<CellLinkedList<D>> cells;  // the patch's particles, for wall-force models
    std::unique_ptr<PatchMotion<D>> motion;  // prescribed motion; none for a fixed patch
    bool surfaceAlongCurve = false;          // a deforming 2D patch whose normals follow its chords
    int wallField = -1;                      // the value its walls hold in the field `patch` (-1: none)
};

}  // namespace sph
