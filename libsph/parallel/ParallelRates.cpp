#include "parallel/ParallelRates.hpp"

#include "core/FatalError.hpp"
#include "driver/CaseDirectory.hpp"
#include "driver/FluidSetup.hpp"
#include "driver/Threads.hpp"
#include "io/TimeName.hpp"
#include "parallel/HaloExchange.hpp"
#include "parallel/ParticlePieces.hpp"
#include "parallel/RcbPartition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace sph::parallel {

namespace {

// A particle's place in the serial run's storage: a rank keeps its particles in this order.
constexpr IntegerField serialOrder{"serialOrder"};

template <int D>
std::optional<std::string> notYetOnSeveralRanks(const FluidSystem<D>& system) {
    if (std::holds_alternative<Antuono2010>(system.models().diffusion)) return "delta-SPH's density diffusion (antuono)";
    for (const Patch<D>& patch : system.patches) {
        if (patch.motion) return "a moving patch ('" + patch.name + "')";
        const std::string model = patch.model->describe();
        if (model != "dynamicBoundary" && !model.starts_with("dummyParticles"))
            return "the boundary model of patch '" + patch.name + "' (" + model + "; so far dynamicBoundary and dummyParticles)";
    }
    return std::nullopt;
}

// The particles of `set` this rank owns.
template <int D>
ParticleSet<D> ownedPart(const Communicator& ranks, const ParticleSet<D>& set, const DomainBoxes<D>& boxes) {
    ParticleSet<D> owned = set;
    std::vector<std::uint32_t> mine;
    for (std::size_t i = 0; i < owned.size(); ++i)
        if (boxes.ownerOf(owned.position[i]) == ranks.rank()) mine.push_back(static_cast<std::uint32_t>(i));
    owned.keep(mine);
    return owned;
}

// This rank's particles of a set (which holds serialOrder) and the copies of others' within the
// halo width of its box, all in the serial order, with the exchange that refreshes the copies.
template <int D>
struct Share {
    ParticleSet<D> particles;
    HaloExchange<D> halos;
};

template <int D>
Share<D> shareOf(const Communicator& ranks, const ParticleSet<D>& set, const DomainBoxes<D>& boxes, double width) {
    ParticleSet<D> share = ownedPart(ranks, set, boxes);
    HaloExchange<D> halos(ranks, share, boxes, width);
    std::vector<std::uint32_t> serial(share.size());
    std::iota(serial.begin(), serial.end(), 0u);
    const auto& place = share[serialOrder];
    std::sort(serial.begin(), serial.end(), [&](std::uint32_t a, std::uint32_t b) { return place[a] < place[b]; });
    share.keep(serial);
    halos.reorder(serial);
    return {std::move(share), std::move(halos)};
}

template <int D>
void ratesOfDimension(const Communicator& ranks, const std::filesystem::path& caseDirectory, const TimeDirectory& start, std::optional<int> threads) {
    CaseSetup<D> setup = setUpCase<D>(caseDirectory, start);
    FluidSystem<D>& system = *setup.system;
    const double startTime = setup.header.time;
    // The model dictionaries are read whole: a keyword no model took stops the run. controlDict's
    // run controls and function objects are the time loop's (which -parallel does not run yet).
    for (const Dictionary& dict : setup.dictionaries) dict.checkUnused();
    if (const std::optional<std::string> missing = notYetOnSeveralRanks(system))
        throw FatalError("error: wcsph -parallel does not run " + *missing + " on several ranks yet (issue 23); run the case without -parallel");

    // Every rank holds the whole case: each hands Zoltan every size-th point.
    std::vector<Vec<D>> points;
    std::vector<double> weights;
    const auto stride = static_cast<std::size_t>(ranks.size());
    for (std::size_t i = static_cast<std::size_t>(ranks.rank()); i < system.fluid.size(); i += stride)
        points.push_back(system.fluid.position[i]), weights.push_back(1.0);
    for (std::size_t i = static_cast<std::size_t>(ranks.rank()); i < system.walls.size(); i += stride)
        points.push_back(system.walls.position[i]), weights.push_back(0.1);
    Vec<D> period = Vec<D>::Zero();
    for (int d = 0; d < D; ++d)
        if (system.periodic()[static_cast<std::size_t>(d)]) period[d] = system.domainMax()[d] - system.domainMin()[d];
    const DomainBoxes<D> boxes = partitionByRcb<D>(ranks, points, weights, system.domainMin(), system.domainMax(), period);

    // One evaluation, no particle moves: the kernel support is the halo width.
    const double width = system.supportRadius();
    for (ParticleSet<D>* set : {&system.fluid, &system.walls}) {
        auto& order = set->add(serialOrder, 0, false);
        std::iota(order.begin(), order.end(), 0);
    }
    Share<D> fluid = shareOf(ranks, system.fluid, boxes, width);
    Share<D> walls = shareOf(ranks, system.walls, boxes, width);
    system.adoptParticles(std::move(fluid.particles), std::move(walls.particles));
    // A copy's summed density and a wall copy's extrapolated state lack the particles beyond the
    // halo: the owners' values replace them.
    system.afterSummationDensity = [&] { fluid.halos.refresh(system.fluid, fields::density); };
    system.afterWallUpdate = [&] {
        walls.halos.refresh(system.walls, fields::pressure, fields::density);
        if (system.walls.has(fields::viscousVelocity)) walls.halos.refresh(system.walls, fields::viscousVelocity);
    };
    const RunThreads runThreads(system.fluid.size() + system.walls.size(), D, threads);
    system.evaluateRates(startTime);

    const std::filesystem::path directory = caseDirectory / "postProcessing" / "rates" / timeName(startTime);
    std::optional<std::string> cannotCreate;
    if (ranks.rank() == 0) {
        std::error_code error;
        std::filesystem::remove_all(directory, error);
        if (!std::filesystem::create_directories(directory, error) && error)
            cannotCreate = "error: cannot create '" + directory.string() + "': " + error.message();
    }
    ranks.stopIfAnyFailed(cannotCreate);
    StateHeader header = setup.header;
    header.time = startTime;
    writeParticlePieces(ranks, directory, "fluid", ownedPart(ranks, system.fluid, boxes), header);
    header.patchNames = setup.patchNames;
    writeParticlePieces(ranks, directory, "walls", ownedPart(ranks, system.walls, boxes), header);
    fmt::print("\nWrote the right-hand side at t = {:g} on {} ranks to {} (fluid.pvtu, walls.pvtu)\n", startTime, ranks.size(), directory.string());
}

}  // namespace

void writeRatesInParallel(const Communicator& ranks, const std::filesystem::path& caseDirectory, std::optional<int> threads) {
    if (!std::filesystem::is_directory(caseDirectory)) throw FatalError("error: case directory '" + caseDirectory.string() + "' does not exist");
    const Dictionary controlDict = readCaseDictionary(caseDirectory, "system/controlDict");
    controlDict.findEntry("application");
    const TimeDirectory start = selectStartTime(caseDirectory, controlDict);
    const int dimension = readParticleFileHeader(start.path / "fluid.vtu").dimension;
#ifdef SPHKIT_HAS_2D
    if (dimension == 2) return ratesOfDimension<2>(ranks, caseDirectory, start, threads);
#endif
#ifdef SPHKIT_HAS_3D
    if (dimension == 3) return ratesOfDimension<3>(ranks, caseDirectory, start, threads);
#endif
    throw FatalError(fmt::format("error: wcsph -parallel runs the 2D and 3D cases this build compiled, and '{}' is {}D",
                                 (start.path / "fluid.vtu").string(), dimension));
}

}  // namespace sph::parallel
