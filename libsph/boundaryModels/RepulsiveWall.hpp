// A patch whose particles repel the fluid by a force law (Monaghan & Kajtar 2009 or
// Lennard-Jones after Monaghan 1994) instead of entering its kernel sums. The loop is a
// template over the law and the kernel, dispatched once per evaluation; the deficiency
// correction uses the same loop for its repulsion partner.
// Examples (constant/boundaryProperties):
//   tank { type monaghanKajtar; K 10; }
//   tank { type lennardJones; Dc 10; }
#pragma once

#include "boundaryModels/BoundaryModel.hpp"
#include "boundaryModels/LennardJonesMonaghan1994.hpp"
#include "boundaryModels/MonaghanKajtar2009.hpp"

#include <variant>

namespace sph {

using RepulsionLaw = std::variant<MonaghanKajtar2009, LennardJonesMonaghan1994>;

// Reads `type monaghanKajtar | lennardJones` and its coefficients from `dict`.
RepulsionLaw readRepulsionLaw(const Dictionary& dict, const ModelContext& context);
std::string describe(const RepulsionLaw& law);
// How far the law repels: the kernel support (Monaghan-Kajtar) or r0 (Lennard-Jones).
double repulsionRange(const RepulsionLaw& law, double support);

// Adds the repulsion of the patch's particles (indexed by patchCells) to every fluid particle.
template <int D>
void addRepulsion(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, const RepulsionLaw& law);

template <int D>
class RepulsiveWall : public BoundaryModel<D> {
public:
    explicit RepulsiveWall(RepulsionLaw law) : law_(law) {}
    bool actsThroughWallParticles() const override { return false; }
    std::string describe() const override { return sph::describe(law_); }
    double reach(double support) const override { return repulsionRange(law_, support); }
    void addWallForces(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, std::size_t, std::size_t) override {
        addRepulsion(view, patchCells, law_);
    }

private:
    RepulsionLaw law_;
};

}  // namespace sph
