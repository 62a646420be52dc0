#include "parallel/DistributedSystem.hpp"

#include "io/ParticleState.hpp"
#include "motion/MovingWallPatch.hpp"
#include "parallel/GatheredParticles.hpp"
#include "parallel/ParticleMigration.hpp"
#include "parallel/RcbPartition.hpp"

#include <nvector/nvector_mpimanyvector.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace sph::parallel {

namespace {

std::vector<std::uint32_t> ownedPlaces(const std::vector<char>& owned) {
    std::vector<std::uint32_t> places;
    for (std::size_t i = 0; i < owned.size(); ++i)
        if (owned[i]) places.push_back(static_cast<std::uint32_t>(i));
    return places;
}

// The global ids of the particles a rank owns, in their order.
template <int D>
std::vector<std::int64_t> ownedIds(const ParticleSet<D>& set, const std::vector<char>& owned) {
    std::vector<std::int64_t> ids;
    for (std::size_t i = 0; i < set.size(); ++i)
        if (owned[i]) ids.push_back(set.globalId[i]);
    return ids;
}

// The farthest any selected model reads from an owned particle: the kernel support, twice it
// where a pass reads what another computed over its neighbours (delta-SPH's density gradient;
// shifting's free-surface normals and density gradient), the boundary models' reach.
template <int D>
double haloReach(const FluidSystem<D>& system) {
    const bool chained = std::holds_alternative<Antuono2010>(system.models().diffusion) || system.shiftsParticles();
    double reach = (chained ? 2.0 : 1.0) * system.supportRadius();
    for (const Patch<D>& patch : system.patches) reach = std::max(reach, patch.model->reach(system.supportRadius()));
    return reach;
}

}  // namespace

template <int D>
DistributedSystem<D>::DistributedSystem(const Communicator& ranks, FluidSystem<D>& system, double wallWeight)
    : ranks_(ranks),
      system_(system),
      skin_(skinPerSupport * system.supportRadius()),
      wallsMove_(std::any_of(system.patches.begin(), system.patches.end(), [](const Patch<D>& patch) { return patch.motion != nullptr; })),
      // A model's reach may follow from the walls it holds (mDBC's deepest layer).
      width_(ranks.maxOverRanks(haloReach(system)) + skin_),
      wallWeight_(wallWeight),
      boxes_({}, Vec<D>::Zero()) {
    std::vector<std::uint32_t> fluidPlaces(system.fluid.size()), wallPlaces(system.walls.size());
    std::iota(fluidPlaces.begin(), fluidPlaces.end(), 0u);
    std::iota(wallPlaces.begin(), wallPlaces.end(), 0u);
    partition(fluidPlaces, wallPlaces, 1.0);

    ParticleSet<D> fluid = std::move(system.fluid), walls = std::move(system.walls);
    // The serial run sorts its walls by patch, in the patches' order, keeping the state's order
    // within each: a wall's orderCell is its patch's place.
    auto& wallPatchPlace = walls[fields::orderCell];
    for (std::size_t p = 0; p < system.patches.size(); ++p)
        std::fill(wallPatchPlace.begin() + static_cast<std::ptrdiff_t>(system.patches[p].begin),
                  wallPatchPlace.begin() + static_cast<std::ptrdiff_t>(system.patches[p].end), static_cast<int>(p));
    migrateParticles(ranks, fluid, boxes_);
    migrateParticles(ranks, walls, boxes_);
    agreeOnSurfacesAlongCurves(walls);
    fluidHalos_.emplace(shareWithNeighbours(fluid, fluidOwned_));
    wallHalos_.emplace(shareWithNeighbours(walls, wallsOwned_));
    system.adoptParticles(std::move(fluid), std::move(walls));
    positionsAtRedistribution_ = system.fluid.position;
    wallPositionsAtRedistribution_ = system.walls.position;
    refreshWithinEvaluations();
}

template <int D>
void DistributedSystem<D>::agreeOnSurfacesAlongCurves(const ParticleSet<D>& walls) {
    for (std::size_t p = 0; p < system_.patches.size(); ++p) {
        Patch<D>& patch = system_.patches[p];
        if (!patch.motion || !patch.motion->deforms()) continue;
        std::vector<std::uint32_t> mine;
        const auto& place = walls[fields::orderCell];
        for (std::size_t w = 0; w < walls.size(); ++w)
            if (place[w] == static_cast<int>(p)) mine.push_back(static_cast<std::uint32_t>(w));
        ParticleSet<D> patchWalls = walls;
        patchWalls.keep(mine);
        gatherToFirst(ranks_, patchWalls);
        std::array<double, 1> alongCurve{ranks_.rank() == 0 && surfaceAlongCurve(patchWalls, 0, patchWalls.size()) ? 1.0 : 0.0};
        ranks_.broadcastFromFirst(alongCurve);
        patch.surfaceAlongCurve = alongCurve[0] > 0.0;
    }
}

template <int D>
void DistributedSystem<D>::partition(const std::vector<std::uint32_t>& fluid, const std::vector<std::uint32_t>& walls, double weightPerParticle) {
    // The box the fluid's reach spans now (every rank's fluid, grown by the halo width).
    std::vector<double> bounds(2 * D, std::numeric_limits<double>::lowest());  // -lower, upper
    for (const std::uint32_t i : fluid)
        for (int d = 0; d < D; ++d) {
            const auto dd = static_cast<std::size_t>(d);
            bounds[dd] = std::max(bounds[dd], -system_.fluid.position[i][d]);
            bounds[D + dd] = std::max(bounds[D + dd], system_.fluid.position[i][d]);
        }
    ranks_.maxOverRanks(bounds);
    for (int d = 0; d < D; ++d)
        fluidReach_.lower[d] = -bounds[static_cast<std::size_t>(d)] - width_, fluidReach_.upper[d] = bounds[static_cast<std::size_t>(D + d)] + width_;
    std::vector<Vec<D>> points;
    std::vector<double> weights;
    for (const std::uint32_t i : fluid) points.push_back(system_.fluid.position[i]), weights.push_back(weightPerParticle);
    for (const std::uint32_t i : walls)
        if (weighs(system_.walls.position[i])) points.push_back(system_.walls.position[i]), weights.push_back(wallWeight_ * weightPerParticle);
    Vec<D> period = Vec<D>::Zero();
    for (int d = 0; d < D; ++d)
        if (system_.periodic()[static_cast<std::size_t>(d)]) period[d] = system_.domainMax()[d] - system_.domainMin()[d];
    boxes_ = partitionByRcb<D>(ranks_, points, weights, system_.domainMin(), system_.domainMax(), period);
    boxes_.alignToCells(system_.fluidCells());
}

template <int D>
bool DistributedSystem<D>::weighs(const Vec<D>& wall) const {
    return (wall.array() >= fluidReach_.lower.array()).all() && (wall.array() <= fluidReach_.upper.array()).all();
}

template <int D>
double DistributedSystem<D>::ownedWeight() const {
    std::size_t walls = 0;
    for (std::size_t w = 0; w < system_.walls.size(); ++w) walls += wallsOwned_[w] != 0 && weighs(system_.walls.position[w]);
    return static_cast<double>(ownedFluidCount()) + wallWeight_ * static_cast<double>(walls);
}

template <int D>
void DistributedSystem<D>::repartition(double weightPerParticle) {
    partition(ownedPlaces(fluidOwned_), ownedPlaces(wallsOwned_), weightPerParticle);
    (void)redistributeParticles(true, true);
}

template <int D>
HaloExchange<D> DistributedSystem<D>::shareWithNeighbours(ParticleSet<D>& set, std::vector<char>& owned) {
    const std::size_t ownedCount = set.ownedCount();
    HaloExchange<D> halos(ranks_, set, boxes_, width_);
    const std::vector<std::uint32_t> order = serialOrder(set);
    set.keep(order);
    halos.reorder(order);
    owned.resize(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) owned[i] = order[i] < ownedCount;
    return halos;
}

template <int D>
void DistributedSystem<D>::numberByCell(ParticleSet<D>& fluid) const {
    const CellLinkedList<D>& cells = system_.fluidCells();
    auto& orderCells = fluid[fields::orderCell];
    auto& orderRanks = fluid[fields::orderRank];
    // By the new cell, then the place before (as the serial run's stable sort by cell), packed
    // with the index into one array of keys: (cell, orderCell) and (orderRank, index).
    std::vector<std::pair<std::uint64_t, std::uint64_t>> keys(fluid.size());
    for (std::size_t i = 0; i < fluid.size(); ++i) {
        const auto cell = static_cast<std::uint32_t>(cells.cellIndex(fluid.position[i]));
        keys[i] = {(std::uint64_t{cell} << 32) | static_cast<std::uint32_t>(orderCells[i]),
                   (std::uint64_t{static_cast<std::uint32_t>(orderRanks[i])} << 32) | i};
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::size_t i = keys[k].second & 0xffffffffu;
        const auto cell = static_cast<std::uint32_t>(keys[k].first >> 32);
        const bool sameCell = k > 0 && keys[k - 1].first >> 32 == cell;
        orderRanks[i] = sameCell ? orderRanks[keys[k - 1].second & 0xffffffffu] + 1 : 0;
        orderCells[i] = static_cast<int>(cell);
    }
}

template <int D>
bool DistributedSystem<D>::redistribute(bool sortByCell) {
    return redistributeParticles(sortByCell, wallsMove_);
}

template <int D>
std::size_t DistributedSystem<D>::giveUpOwnedFluid(const std::vector<std::uint32_t>& places) {
    std::size_t given = 0;
    for (const std::uint32_t i : places) {
        given += fluidOwned_[i] != 0;
        fluidOwned_[i] = 0;
    }
    return given;
}

template <int D>
bool DistributedSystem<D>::redistributeParticles(bool sortByCell, bool walls) {
    ParticleSet<D>& fluid = system_.fluid;
    const std::vector<std::int64_t> fluidBefore = ownedIds(fluid, fluidOwned_);
    fluid.keep(ownedPlaces(fluidOwned_));
    migrateParticles(ranks_, fluid, boxes_);
    if (sortByCell) numberByCell(fluid);
    fluidHalos_.emplace(shareWithNeighbours(fluid, fluidOwned_));
    positionsAtRedistribution_ = fluid.position;
    bool ownedChanged = ownedIds(fluid, fluidOwned_) != fluidBefore;
    if (!walls) return ownedChanged;
    // Moving walls go where the fluid goes (and every wall after a repartition); the patches'
    // ranges follow.
    ParticleSet<D> wallSet = system_.walls;
    const std::vector<std::int64_t> wallsBefore = ownedIds(wallSet, wallsOwned_);
    wallSet.keep(ownedPlaces(wallsOwned_));
    migrateParticles(ranks_, wallSet, boxes_);
    wallHalos_.emplace(shareWithNeighbours(wallSet, wallsOwned_));
    ownedChanged = ownedChanged || ownedIds(wallSet, wallsOwned_) != wallsBefore;
    system_.adoptParticles(std::move(system_.fluid), std::move(wallSet));
    wallPositionsAtRedistribution_ = system_.walls.position;
    return ownedChanged;
}

template <int D>
double DistributedSystem<D>::largestDisplacement() const {
    const Vec<D>& period = boxes_.period();
    const auto largestOf = [&](const std::vector<Vec<D>>& x, const std::vector<Vec<D>>& before) {
        double largest2 = 0.0;
#pragma omp parallel for reduction(max : largest2) schedule(static)
        for (std::size_t i = 0; i < x.size(); ++i) {
            Vec<D> moved = x[i] - before[i];
            for (int d = 0; d < D; ++d)
                if (period[d] > 0.0) moved[d] -= period[d] * std::nearbyint(moved[d] / period[d]);
            largest2 = std::max(largest2, moved.squaredNorm());
        }
        return std::sqrt(largest2);
    };
    const double fluid = largestOf(system_.fluid.position, positionsAtRedistribution_);
    return wallsMove_ ? std::max(fluid, largestOf(system_.walls.position, wallPositionsAtRedistribution_)) : fluid;
}

template <int D>
std::vector<int> DistributedSystem<D>::neighbourRanks() const {
    std::vector<int> ranks = fluidHalos_->neighbours();
    ranks.insert(ranks.end(), wallHalos_->neighbours().begin(), wallHalos_->neighbours().end());
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
    return ranks;
}

template <int D>
std::vector<std::uint32_t> DistributedSystem<D>::ownedFluidPlaces() const {
    return ownedPlaces(fluidOwned_);
}

template <int D>
std::vector<std::uint32_t> DistributedSystem<D>::ownedWallPlaces() const {
    return ownedPlaces(wallsOwned_);
}

template <int D>
ParticleSet<D> DistributedSystem<D>::selected(const ParticleSet<D>& set, const std::vector<char>& owned) {
    ParticleSet<D> part = set;
    part.keep(ownedPlaces(owned));
    return part;
}

template <int D>
template <class Exchange>
void DistributedSystem<D>::timed(Exchange&& exchange) {
    const auto start = std::chrono::steady_clock::now();
    exchange();
    exchangeSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <int D>
void DistributedSystem<D>::refreshShifted() {
    timed([this] {
        ParticleSet<D>& fluid = system_.fluid;
        if (system_.continuity())
            fluidHalos_->refreshPositions(fluid, fields::density);
        else
            fluidHalos_->refreshPositions(fluid);
    });
}

// The owned particles' shares (a copy's repeats its owner's) with their places in the serial
// order, from every rank, sorted by that place: the serial run's storage order, in which it sums
// them.
template <int D>
std::vector<BodyLoadShare<D>> DistributedSystem<D>::bodyLoadSharesOfAllRanks(const std::vector<BodyLoadShare<D>>& mine) const {
    constexpr std::size_t width = D + 3;  // orderCell, orderRank, force, torque: whole numbers below 2^32 exact as doubles
    const auto& cell = system_.fluid[fields::orderCell];
    const auto& rank = system_.fluid[fields::orderRank];
    std::vector<double> packed;
    packed.reserve(width * mine.size());
    for (const BodyLoadShare<D>& share : mine) {
        if (!fluidOwned_[share.particle]) continue;
        packed.push_back(static_cast<std::uint32_t>(cell[share.particle]));  // as serialPlace orders cells
        packed.push_back(rank[share.particle]);
        for (int d = 0; d < D; ++d) packed.push_back(share.force[d]);
        packed.push_back(share.torque);
    }
    const std::vector<double> gathered = ranks_.gatherToAll(packed);
    std::vector<std::size_t> order(gathered.size() / width);
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto place = [&](std::size_t s) { return std::pair{gathered[s * width], gathered[s * width + 1]}; };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return place(a) < place(b); });
    std::vector<BodyLoadShare<D>> all;
    for (const std::size_t s : order) {
        BodyLoadShare<D> share{s, Vec<D>::Zero(), gathered[s * width + D + 2]};
        for (int d = 0; d < D; ++d) share.force[d] = gathered[s * width + 2 + d];
        all.push_back(share);
    }
    return all;
}

template <int D>
void DistributedSystem<D>::refreshWithinEvaluations() {
    FluidSystem<D>& system = system_;
    system.afterSummationDensity = [this] { timed([this] { fluidHalos_->refresh(system_.fluid, fields::density); }); };
    // Only a wall state set from the fluid (dummy particles) differs on a copy: one that is
    // integrated (dynamic boundary) advances as its owner's, and wall-force models set none.
    const bool wallStateFromFluid = std::any_of(system.patches.begin(), system.patches.end(), [](const Patch<D>& patch) {
        return patch.model->actsThroughWallParticles() && !patch.model->evolvesWallDensity();
    });
    if (wallStateFromFluid)
        system.afterWallUpdate = [this] {
            timed([this] {
                ParticleSet<D>& walls = system_.walls;
                if (walls.has(fields::viscousVelocity))
                    wallHalos_->refresh(walls, fields::pressure, fields::density, fields::viscousVelocity);
                else
                    wallHalos_->refresh(walls, fields::pressure, fields::density);
            });
        };
    if (std::any_of(system.patches.begin(), system.patches.end(), [](const Patch<D>& patch) { return patch.surfaceAlongCurve; }))
        system.afterWallMotion = [this] { timed([this] { wallHalos_->refresh(system_.walls, fields::normal, fields::spacing, fields::area); }); };
    system.largestOverRanks = [this](double value) { return ranks_.maxOverRanks(value); };
    if (!system.freeBodyPatches().empty())
        system.bodyLoadsOverRanks = [this](const std::vector<BodyLoadShare<D>>& mine) {
            std::vector<BodyLoadShare<D>> all;
            timed([&] { all = bodyLoadSharesOfAllRanks(mine); });
            return all;
        };
    // The copies' own rates are replaced by their owners', unless a wall-force model reads them
    // first (the deficiency correction samples the uncorrected acceleration around its walls).
    const bool copiesRatesRead =
        std::any_of(system.patches.begin(), system.patches.end(), [](const Patch<D>& patch) { return patch.model->needsUncorrectedAcceleration(); });
    if (!copiesRatesRead) system.ratesWanted = &fluidOwned_;
    system.ownedFluid = &fluidOwned_;
    shareStateWithSundials();
    system.afterRates = [this] {
        timed([this] {
            if (system_.continuity())
                fluidHalos_->refresh(system_.fluid, fields::acceleration, fields::densityRate);
            else
                fluidHalos_->refresh(system_.fluid, fields::acceleration);
            if (system_.wallDensityEvolves()) wallHalos_->refresh(system_.walls, fields::densityRate);
        });
    };
}

template <int D>
void DistributedSystem<D>::shareStateWithSundials() {
    StateOverRanks& state = stateOverRanks_;
    state.fluidOwned = &fluidOwned_;
    state.wallsOwned = &wallsOwned_;
    state.refreshCopies = [this] {
        timed([this] {
            ParticleSet<D>& fluid = system_.fluid;
            if (system_.continuity())
                fluidHalos_->refreshPositions(fluid, fields::velocity, fields::density);
            else
                fluidHalos_->refreshPositions(fluid, fields::velocity);
            if (system_.wallDensityEvolves()) wallHalos_->refresh(system_.walls, fields::density);
        });
    };
    state.onAnyRank = [this](bool value) { return ranks_.maxOverRanks(value ? 1.0 : 0.0) > 0.0; };
    state.join = [this](std::vector<N_Vector>& parts, SUNContext context) {
        return N_VMake_MPIManyVector(ranks_.handle(), static_cast<sunindextype>(parts.size()), parts.data(), context);
    };
    state.subvectorData = N_VGetSubvectorArrayPointer_MPIManyVector;
    state.stopAll = [this](const std::string& message) {
        std::fprintf(stderr, "rank %d of %d: %s\n", ranks_.rank(), ranks_.size(), message.c_str());
        std::fflush(stderr);
        MPI_Abort(ranks_.handle(), 1);
    };
    system_.stateOverRanks = &stateOverRanks_;
}

template <int D>
FluidSystemView<D> DistributedSystem<D>::view() const {
    FluidSystemView<D> share = system_.view();
    share.fluidOwned = fluidOwned_;
    share.wallsOwned = wallsOwned_;
    share.answersForPoint = [this](const Vec<D>& x) { return boxes_.ownerOf(x) == ranks_.rank(); };
    return share;
}

#define SPHKIT_INSTANTIATE(D) template class DistributedSystem<D>;
#ifdef SPHKIT_HAS_2D
SPHKIT_INSTANTIATE(2)
#endif
#ifdef SPHKIT_HAS_3D
SPHKIT_INSTANTIATE(3)
#endif
#undef SPHKIT_INSTANTIATE

}  // namespace sph::parallel
