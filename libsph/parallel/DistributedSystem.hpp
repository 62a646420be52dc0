// One rank's share of a FluidSystem in a decomposed run: the particles it owns and copies of
// the others' within the halo width of its box, stored together in the order the serial run
// stores them. Every sum over neighbours then adds its terms in the serial sequence, and a run
// on N ranks equals the serial run bit for bit.
//
// The serial order: the serial run sorts its fluid by cell every stepsBetweenCellSorts steps, and
// the sort is stable, so a particle's place follows from (its cell at the last sort, its place
// among that cell's particles in the order before). Both numbers are fields of the particle
// (orderCell, orderRank). A rank numbers the particles of the cells it owns; it owns whole cells
// (DomainBoxes::alignToCells), so it holds all of a cell's particles when it numbers them. The
// walls never move: their order is their place in the state file.
//
// Between two redistributions the copies are advanced by a native integrator like their owners,
// with their owners' rates (refreshed at the end of each evaluation), so they stay equal to them
// without resending the state (a SUNDIALS integrator advances the owned particles only and sends
// the copies their state before each evaluation: StateOverRanks); the copies' summed density and wall state are refreshed where
// they are computed. A copy's own rates miss the neighbours beyond the halo and are never used:
// the pair loop skips the pairs of two copies (FluidSystem::ratesWanted) unless a model reads
// them within the evaluation.
#pragma once

#include "parallel/Communicator.hpp"
#include "parallel/DomainBoxes.hpp"
#include "parallel/HaloExchange.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/StateOverRanks.hpp"

#include <algorithm>
#include <optional>
#include <string>

namespace sph::parallel {

template <int D>
class DistributedSystem {
public:
    // The halo reaches this far past what the models read (in kernel supports), so that the
    // particles may move a while before the halos are built again: no particle may move more
    // than half of it between two builds (largestDisplacement).
    static constexpr double skinPerSupport = 0.2;

    // Collective. Each rank holds a share of the case in `system` (every particle on one rank,
    // StateShare), each particle's place in the serial order in the fields orderCell and
    // orderRank; keeps the particles its box holds, and copies of the others' within the halo
    // width. Walls weigh `wallWeight` fluid particles in the partition.
    DistributedSystem(const Communicator& ranks, FluidSystem<D>& system, double wallWeight = 0.1);

    // Collective. Every fluid particle (and wall particle of a moving patch) to the rank that
    // owns its cell now, and new halos; `sortByCell` where the serial run sorts its fluid by cell
    // (new order numbers; walls keep theirs). Returns whether the particles this rank owns, or
    // their order, changed.
    [[nodiscard]] bool redistribute(bool sortByCell);
    // Gives up the owned fluid particles among `places` (held places, ascending): the next
    // redistribute drops them, copies included. Returns how many this rank owned.
    std::size_t giveUpOwnedFluid(const std::vector<std::uint32_t>& places);

    // Collective. New boxes, each owned particle weighing weightPerParticle (a wall
    // wallWeight times that): a rank passes its measured cost per particle, so that the next
    // boxes even out the time, not the count. Then every particle to its new owner, sorted by
    // cell: call where the serial run sorts.
    void repartition(double weightPerParticle);
    // What this rank's owned particles weigh in the partition at 1 per fluid particle (the
    // walls that no fluid reaches weigh nothing: weighs()).
    double ownedWeight() const;

    // Collective. After FluidSystem::shiftParticles: the owners' shifted positions (and densities)
    // to their copies, which the shift computed from incomplete neighbourhoods.
    void refreshShifted();

    // The farthest a particle this rank holds, fluid or wall, moved since the last
    // redistribution (over periodic seams, the shortest way).
    double largestDisplacement() const;
    double skin() const { return skin_; }

    // This rank's owned particles, in the serial order (for output): a set of their own, or
    // their places among the particles the rank holds (no copy of every array).
    ParticleSet<D> ownedFluid() const { return selected(system_.fluid, fluidOwned_); }
    ParticleSet<D> ownedWalls() const { return selected(system_.walls, wallsOwned_); }
    const ParticleSet<D>& heldFluid() const { return system_.fluid; }
    const ParticleSet<D>& heldWalls() const { return system_.walls; }
    std::vector<std::uint32_t> ownedFluidPlaces() const;
    std::vector<std::uint32_t> ownedWallPlaces() const;
    std::size_t ownedFluidCount() const { return ownedCount(fluidOwned_); }
    std::size_t ownedWallCount() const { return ownedCount(wallsOwned_); }

    // The halo width, the ranks this one exchanges with (ascending), and what the halo
    // exchanges sent so far: bytes and messages.
    double haloWidth() const { return width_; }
    std::vector<int> neighbourRanks() const;
    std::size_t haloBytesSent() const { return fluidHalos_->bytesSent() + wallHalos_->bytesSent(); }
    std::size_t haloMessagesSent() const { return fluidHalos_->messagesSent() + wallHalos_->messagesSent(); }
    // The wall time the halo refreshes took so far, waits for the neighbours included (the
    // redistributions are not counted: the caller times them).
    double exchangeSeconds() const { return exchangeSeconds_; }

    const DomainBoxes<D>& boxes() const { return boxes_; }

    // This rank's share as function objects read it: the particles it holds, which of them it
    // owns, and the sample points it answers for (those in the cells it owns). Valid until the
    // next redistribution.
    FluidSystemView<D> view() const;

private:
    // Boxes from the particles at the given places (each rank passes its own), fluid weighing
    // weightPerParticle, walls wallWeight_ times that. Walls that no fluid reaches cost
    // nothing, but they would stretch the box that the bisection cuts across, longest side first
    // (a dam break's tank beyond the water): only the walls within the halo width of the fluid's
    // bounding box take part; the others go to whichever box holds them.
    void partition(const std::vector<std::uint32_t>& fluid, const std::vector<std::uint32_t>& walls, double weightPerParticle);
    // Whether a wall at x takes part in the partition: inside the fluid's reach at the last one.
    bool weighs(const Vec<D>& wall) const;
    [[nodiscard]] bool redistributeParticles(bool sortByCell, bool walls);
    static std::size_t ownedCount(const std::vector<char>& owned) { return static_cast<std::size_t>(std::count(owned.begin(), owned.end(), 1)); }
    static ParticleSet<D> selected(const ParticleSet<D>& set, const std::vector<char>& owned);
    // Copies of the others' particles within the halo width, the set's particles (owned ones
    // only on entry) in the serial order after; returns the exchange that refreshes the copies.
    HaloExchange<D> shareWithNeighbours(ParticleSet<D>& set, std::vector<char>& owned);
    void numberByCell(ParticleSet<D>& fluid) const;
    // Whether each deforming patch's surface runs along one curve (FluidSystem's patch flag),
    // decided on rank 0 from the whole patch: a share of it has gaps.
    void agreeOnSurfacesAlongCurves(const ParticleSet<D>& walls);
    void refreshWithinEvaluations();
    // What the SUNDIALS integrators need to advance this rank's share (StateOverRanks).
    void shareStateWithSundials();
    std::vector<BodyLoadShare<D>> bodyLoadSharesOfAllRanks(const std::vector<BodyLoadShare<D>>& mine) const;
    template <class Exchange>
    void timed(Exchange&& exchange);

    Communicator ranks_;
    FluidSystem<D>& system_;
    double skin_;
    bool wallsMove_;
    double width_;
    double wallWeight_;
    DomainBoxes<D> boxes_;
    RankBox<D> fluidReach_;                      // the fluid's bounding box at the last partition, grown by the halo width
    std::vector<char> fluidOwned_, wallsOwned_;  // per particle held: 1 if this rank owns it
    std::optional<HaloExchange<D>> fluidHalos_, wallHalos_;
    std::vector<Vec<D>> positionsAtRedistribution_, wallPositionsAtRedistribution_;
    double exchangeSeconds_ = 0.0;
    StateOverRanks stateOverRanks_;
};

}  // namespace sph::parallel
