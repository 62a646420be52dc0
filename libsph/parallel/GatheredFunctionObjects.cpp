#include "parallel/GatheredFunctionObjects.hpp"

#include "core/FieldBytes.hpp"
#include "io/ParticleState.hpp"

#include <fmt/format.h>

#include <numeric>
#include <span>
#include <utility>

namespace sph::parallel {

namespace {

// Every rank's particles of `set` on rank 0, in the serial order; `set` is left empty elsewhere.
template <int D>
void gatherToFirst(const Communicator& ranks, ParticleSet<D>& set) {
    std::vector<std::uint32_t> all(set.size());
    std::iota(all.begin(), all.end(), 0u);
    std::vector<std::byte> mine;
    pack(everyArray(set), all, mine);
    std::vector<std::size_t> fromRank;
    const std::vector<std::byte> gathered = ranks.gatherToFirst(mine, fromRank);
    if (ranks.rank() != 0) {
        set.resize(0);
        return;
    }
    const std::size_t record = bytesPerParticle(everyArray(set));
    set.resize(record > 0 ? gathered.size() / record : 0);
    const std::vector<FieldBytes> arrays = everyArray(set);
    std::size_t next = 0, offset = 0;
    for (const std::size_t bytes : fromRank) {
        next += unpack(arrays, next, std::span(gathered).subspan(offset, bytes));
        offset += bytes;
    }
    set.permute(serialOrder(set));
}

}  // namespace

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
