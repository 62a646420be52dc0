#include "parallel/GatheredFunctionObjects.hpp"

#include "parallel/GatheredParticles.hpp"

#include <fmt/format.h>

#include <utility>

namespace sph::parallel {

template <int D>
GatheredFunctionObjects<D>::GatheredFunctionObjects(const Communicator& ranks, const std::filesystem::path& caseDirectory, const TimeDirectory& start,
                                                    const Dictionary& controlDict, double rho0)
    : ranks_(ranks) {
    any_ = controlDict.found("functions");
    if (!any_) return;
    together(ranks, [&] {
        if (ranks.rank() != 0) return;
        fmt::print("\nFunction objects: rank 0 reads the case again, to hold the whole state for them\n");
        whole_.emplace(setUpCase<D>(caseDirectory, start));
        schedule_.emplace(controlDict, caseDirectory, whole_->header.time, rho0, whole_->system->view());
    });
}

template <int D>
void GatheredFunctionObjects<D>::execute(const DistributedSystem<D>& shared, FluidSystem<D>& running, double t, bool force) {
    if (!any_) return;
    ParticleSet<D> fluid = shared.ownedFluid(), walls = shared.ownedWalls();
    gatherToFirst(ranks_, fluid);
    gatherToFirst(ranks_, walls);
    if (ranks_.rank() != 0) return;
    FluidSystem<D>& system = *whole_->system;
    system.fluid = std::move(fluid);
    system.walls = std::move(walls);
    // The fixed walls' cells hold; the fluid's are built for the gathered positions.
    CellLinkedList<D> fluidCells = system.fluidCells();
    fluidCells.build(system.fluid.position);
    const FluidSystemView<D> view = system.view();
    const FluidSystemView<D> gathered{view.fluid,     view.walls,     view.patches,       fluidCells,           view.wallCells,
                                      view.kernel,    view.viscosity, view.supportRadius, view.smoothingLength, view.viscous,
                                      view.domainMin, view.domainMax, view.gravity};
    // The motions lent for the execution, and given back however it ends.
    const auto exchangeMotions = [&] {
        for (std::size_t p = 0; p < system.patches.size(); ++p) std::swap(system.patches[p].motion, running.patches[p].motion);
    };
    exchangeMotions();
    try {
        schedule_->execute(gathered, t, force);
    } catch (...) {
        exchangeMotions();
        throw;
    }
    exchangeMotions();
}

template <int D>
void GatheredFunctionObjects<D>::reportErrorAgainstCost(const std::filesystem::path& caseDirectory, double startTime, const RunCost& cost) const {
    if (schedule_) schedule_->reportErrorAgainstCost(caseDirectory, startTime, cost);
}

#ifdef SPHKIT_HAS_2D
template class GatheredFunctionObjects<2>;
#endif
#ifdef SPHKIT_HAS_3D
template class GatheredFunctionObjects<3>;
#endif

}  // namespace sph::parallel
