// A boundary model acts on the wall particles of one patch, in one of two ways:
//  - through wall particles (dummy particles, dynamic boundary): the patch's particles enter the
//    fluid's kernel sums; updateWalls() sets their pressure, density and the velocity the
//    viscous term sees, once per evaluation, before the force loop, which then treats every
//    such wall particle alike and never branches on a patch's model;
//  - by wall forces (repulsion, the deficiency correction): the patch's particles stay out of
//    the kernel sums; addWallForces() adds accelerations to the fluid after the force loop,
//    reading the uncorrected acceleration when it needs it.
#pragma once

#include "boundaryModels/BoundaryView.hpp"
#include "core/Registry.hpp"
#include "io/Dictionary.hpp"
#include "neighbourSearch/CellLinkedList.hpp"
#include "physics/ModelContext.hpp"

#include <cmath>
#include <memory>
#include <string>

namespace sph {

template <int D>
class BoundaryModel {
public:
    virtual ~BoundaryModel() = default;

    // One line for the run log: the type and its coefficients.
    virtual std::string describe() const = 0;

    // True when the patch's particles enter the fluid's kernel sums (dummy, dynamic boundary).
    virtual bool actsThroughWallParticles() const = 0;

    // True when the model sets its particles' pressure each evaluation (what a wallPressure
    // sensor reads; on other patches the sensor extrapolates the fluid as Adami et al. do).
    virtual bool setsWallPressure() const { return actsThroughWallParticles(); }
    // The fewest layers of wall particles the model needs for a kernel of this support; a
    // wall-force model needs exactly one, on the wall surface.
    virtual int minimumLayers(double /*support*/, double /*dx*/) const { return 1; }
    // The layers a patch that names none is generated with (driver/WallLayoutFromModel).
    virtual int layersToGenerate(double support, double dx) const { return minimumLayers(support, dx); }

    // True when the patch's wall density is part of the integrated state.
    virtual bool evolvesWallDensity() const { return false; }

    // How far from a fluid particle lie the particles whose values its rates depend on, through
    // the model's passes (a decomposed run's halos reach this far): the kernel support, unless a
    // pass reads values that another pass computed over its own neighbours.
    virtual double reach(double support) const { return support; }

    // True when addWallForces() adds a viscous stress of its own (a wall-force model's no-slip
    // wall): an integrator that takes the fluid's viscosity implicitly would take it explicitly.
    virtual bool addsViscousStress() const { return false; }

    // True when addWallForces() reads the fluid's acceleration before any wall force.
    virtual bool needsUncorrectedAcceleration() const { return false; }

    // Adds the fields the model reads or writes, once, before the first evaluation.
    virtual void addFields(const BoundaryView<D>& /*view*/) {}

    // Restart from a state the solver wrote after an evaluation: a model whose evaluation
    // carries history (temporal smoothing) repeats that evaluation from the written fields.
    virtual void resume(const BoundaryView<D>& /*view*/, std::size_t /*begin*/, std::size_t /*end*/) {}

    // Stage 3: sets the state of wall particles [begin, end) from the fluid.
    virtual void updateWalls(const BoundaryView<D>& /*view*/, std::size_t /*begin*/, std::size_t /*end*/) {}

    // Stage 5: adds the patch's accelerations to the fluid. `patchCells` indexes the patch's
    // particles [begin, end) of the wall set.
    virtual void addWallForces(const BoundaryView<D>& /*view*/, const CellLinkedList<D>& /*patchCells*/, std::size_t /*begin*/, std::size_t /*end*/) {
    }
};

// Layers of wall particles, the first dx/2 behind the wall, that fill a kernel support behind it.
inline int layersFillingSupport(double support, double dx) { return static_cast<int>(std::ceil(support / dx - 0.5 - 1e-9)); }

template <int D>
using BoundaryModelRegistry = Registry<std::unique_ptr<BoundaryModel<D>>, const Dictionary&, const ModelContext&>;

template <int D>
BoundaryModelRegistry<D> makeBoundaryModelRegistry();

}  // namespace sph
