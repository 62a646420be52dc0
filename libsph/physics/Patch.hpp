// A wall patch: its range of the wall particle set, its boundary model and its motion.
#pragma once

#include "boundaryModels/BoundaryModel.hpp"
#include "core/ExactSum.hpp"
#include "motion/PatchMotion.hpp"
#include "neighbourSearch/CellLinkedList.hpp"

#include <array>
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
    // A wall-force patch whose load a function object reads (`forces`): each evaluation records
    // the reaction of what its wall forces added to the owned fluid, -sum_i m_i (a_i - a_i^before),
    // exactly (the sum over ranks does not depend on how they share the particles).
    bool recordsLoad = false;
    std::array<ExactSum, std::size_t{D}> load{};
};

}  // namespace sph
