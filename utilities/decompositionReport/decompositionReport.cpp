// decompositionReport: how a case's particles would be shared among the ranks mpirun starts (the
// domain decomposition of issue 23, measured before the solver runs on several ranks): owned and
// halo particles per rank, the ranks each exchanges with, the bytes one halo refresh moves, the
// load imbalance, and the memory per rank. The figures feed the weak-scaling model of
// doc/performance.md. Every rank reads the case (this is a measuring tool, not the solver's
// path: rank 0 keeps the particles and the partition hands them out).
#include "core/ExitOnError.hpp"
#include "core/FatalError.hpp"
#include "driver/FluidSetup.hpp"
#include "parallel/Communicator.hpp"
#include "core/FieldBytes.hpp"
#include "parallel/HaloExchange.hpp"
#include "parallel/ParticleMigration.hpp"
#include "parallel/RcbPartition.hpp"

#include <fmt/format.h>

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace {

constexpr const char* usage = R"(Usage: mpirun -np N decompositionReport [OPTIONS]

Partitions a case's start state among the N ranks as the parallel solver will (Zoltan's
recursive coordinate bisection of fluid and wall particles, then migration and halos of width
r_c + 0.4 h) and prints, per rank, the owned and halo particles, the ranks it exchanges with
and the bytes one halo refresh of position, velocity and density moves; then the imbalance,
the halo share and the memory per rank.

Options:
  -case <dir>          case directory (default: the current directory)
  -wallWeight <w>      a wall particle's weight against a fluid particle's 1 (default 0.1)
  -help                print this message
)";

constexpr int statistics = 7;  // per rank: see Report::row

template <int D>
void report(const sph::parallel::Communicator& ranks, const std::filesystem::path& caseDirectory, double wallWeight) {
    using namespace sph;
    const Dictionary controlDict = readCaseDictionary(caseDirectory, "system/controlDict");
    const TimeDirectory start = selectStartTime(caseDirectory, controlDict);
    CaseSetup<D> setup = setUpCase<D>(caseDirectory, start);
    const FluidSystem<D>& system = *setup.system;
    ParticleSet<D> fluid = system.fluid, walls = system.walls;
    if (ranks.rank() != 0) fluid.resize(0), walls.resize(0);

    std::vector<Vec<D>> points(fluid.position);
    points.insert(points.end(), walls.position.begin(), walls.position.end());
    std::vector<double> weights(fluid.size(), 1.0);
    weights.resize(points.size(), wallWeight);
    Vec<D> period = Vec<D>::Zero();
    for (int d = 0; d < D; ++d)
        if (system.periodic()[d]) period[d] = system.domainMax()[d] - system.domainMin()[d];
    const parallel::DomainBoxes<D> boxes = parallel::partitionByRcb<D>(ranks, points, weights, system.domainMin(), system.domainMax(), period);
    parallel::migrateParticles(ranks, fluid, boxes);
    parallel::migrateParticles(ranks, walls, boxes);
    const double width = system.supportRadius() + 0.4 * system.smoothingLength();
    const parallel::HaloExchange<D> fluidHalos(ranks, fluid, boxes, width), wallHalos(ranks, walls, boxes, width);

    // One refresh per evaluation: the fluid's position, velocity and density, the walls' position.
    const std::size_t refreshBytes = fluidHalos.sentCount() * (sizeof(double) * (2 * D + 1)) + wallHalos.sentCount() * sizeof(double) * D;
    std::vector<int> exchangesWith = fluidHalos.neighbours();
    exchangesWith.insert(exchangesWith.end(), wallHalos.neighbours().begin(), wallHalos.neighbours().end());
    std::sort(exchangesWith.begin(), exchangesWith.end());
    exchangesWith.erase(std::unique(exchangesWith.begin(), exchangesWith.end()), exchangesWith.end());
    const std::size_t memory = fluid.size() * bytesPerParticle(everyArray(fluid)) + walls.size() * bytesPerParticle(everyArray(walls));
    const std::array<double, statistics> mine{double(fluid.ownedCount()),
                                              double(walls.ownedCount()),
                                              double(fluid.haloCount()),
                                              double(walls.haloCount()),
                                              double(exchangesWith.size()),
                                              double(refreshBytes),
                                              double(memory)};
    std::vector<double> all(static_cast<std::size_t>(statistics * ranks.size()));
    MPI_Gather(mine.data(), statistics, MPI_DOUBLE, all.data(), statistics, MPI_DOUBLE, 0, ranks.handle());
    const double imbalance = parallel::loadImbalance(ranks, double(fluid.ownedCount()) + wallWeight * double(walls.ownedCount()));
    if (ranks.rank() != 0) return;

    fmt::print("decompositionReport: {}, {}D, {} rank{}, halo width {:.6g} m (support radius {:.6g} + 0.4 h), wall weight {:g}\n",
               caseName(caseDirectory), D, ranks.size(), ranks.size() == 1 ? "" : "s", width, system.supportRadius(), wallWeight);
    fmt::print("{:>5} {:>10} {:>10} {:>11} {:>10} {:>11} {:>11} {:>14} {:>12}\n", "rank", "fluid", "walls", "fluid halo", "wall halo", "halo/owned",
               "neighbours", "refresh bytes", "memory MiB");
    std::array<double, statistics> total{}, largest{};
    for (int r = 0; r < ranks.size(); ++r) {
        const double* row = &all[static_cast<std::size_t>(r * statistics)];
        const double owned = row[0] + row[1], halo = row[2] + row[3];
        fmt::print("{:>5} {:>10} {:>10} {:>11} {:>10} {:>10.1f}% {:>11} {:>14} {:>12.2f}\n", r, row[0], row[1], row[2], row[3],
                   owned > 0 ? 100.0 * halo / owned : 0.0, row[4], row[5], row[6] / 1048576.0);
        for (int s = 0; s < statistics; ++s) total[s] += row[s], largest[s] = std::max(largest[s], row[s]);
    }
    const double owned = total[0] + total[1], halo = total[2] + total[3];
    fmt::print(
        "total: {} fluid and {} wall particles owned, {} halo copies ({:.1f} % of the owned), {} messages per refresh, "
        "{} bytes per refresh\n",
        total[0], total[1], halo, 100.0 * halo / owned, total[4], total[5]);
    fmt::print("load imbalance (largest / mean weight): {:.4f}; memory per rank: largest {:.2f} MiB, mean {:.2f} MiB\n", imbalance,
               largest[6] / 1048576.0, total[6] / ranks.size() / 1048576.0);
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    const sph::parallel::Communicator ranks;
    // The case's set-up echoes every model it selects: once, from rank 0, is enough.
    if (ranks.rank() != 0 && !std::freopen("/dev/null", "w", stdout)) return 1;
    std::string caseDirectory = ".";
    double wallWeight = 0.1;
    int status = 0;
    for (int i = 1; i < argc && status == 0; ++i) {
        const std::string arg = argv[i];
        if (arg == "-help" || arg == "--help" || arg == "-h") {
            fmt::print("{}", usage);
            status = -1;
        } else if (arg == "-case" && i + 1 < argc) {
            caseDirectory = argv[++i];
        } else if (arg == "-wallWeight" && i + 1 < argc) {
            try {
                wallWeight = std::stod(argv[++i]);
            } catch (const std::exception&) {
                wallWeight = -1.0;
            }
            if (!(wallWeight > 0.0)) {
                fmt::print(stderr, "error: -wallWeight takes a positive number, found '{}'\n", argv[i]);
                status = 2;
            }
        } else {
            fmt::print(stderr, "error: unknown or incomplete option '{}'\n\n{}", arg, usage);
            status = 2;
        }
    }
    if (status == 0) {
        status = sph::exitCodeOf([&] {
            const int dimension =
                sph::readParticleFileHeader(sph::selectStartTime(caseDirectory, sph::readCaseDictionary(caseDirectory, "system/controlDict")).path /
                                            "fluid.vtu")
                    .dimension;
#ifdef SPHKIT_HAS_2D
            if (dimension == 2) return report<2>(ranks, caseDirectory, wallWeight);
#endif
#ifdef SPHKIT_HAS_3D
            if (dimension == 3) return report<3>(ranks, caseDirectory, wallWeight);
#endif
            throw sph::FatalError(
                fmt::format("error: decompositionReport takes the 2D and 3D cases this build compiled, and this one is {}D", dimension));
        });
    }
    MPI_Finalize();
    return std::max(status, 0);
}
