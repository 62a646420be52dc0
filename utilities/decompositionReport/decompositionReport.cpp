// decompositionReport: how the parallel solver shares a case's particles among the ranks
// mpirun starts (issue 23), measured with the solver's own DistributedSystem: owned and halo
// particles per rank, the ranks each exchanges with, the bytes and messages the halo exchanges
// send in one evaluation of the rates, the load imbalance, and the memory per rank. The figures
// feed the weak-scaling model of doc/performance.md. Each rank reads its share of the case, as
// the solver does.
#include "core/ExitOnError.hpp"
#include "core/FatalError.hpp"
#include "core/FieldBytes.hpp"
#include "driver/FluidSetup.hpp"
#include "io/ParticleState.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedSystem.hpp"
#include "parallel/RcbPartition.hpp"
#include "parallel/ShareOfCase.hpp"

#include <fmt/format.h>

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace {

constexpr const char* usage = R"(Usage: mpirun -np N decompositionReport [OPTIONS]

Shares a case's start state among the N ranks as wcsph -parallel does (Zoltan's recursive
coordinate bisection of the fluid particles and the wall particles within the fluid's reach
into boxes of whole cells, halos as wide as the models read plus a skin of 0.2 kernel
supports), evaluates the rates once and prints, per rank, the owned and halo particles, the
ranks it exchanges with and the bytes and messages the evaluation's halo refreshes sent; then
the imbalance, the halo share and the memory per rank.

Options:
  -case <dir>          case directory (default: the current directory)
  -wallWeight <w>      a wall particle's weight against a fluid particle's 1 (default 0.1;
                       walls beyond the fluid's reach weigh nothing)
  -help                print this message
)";

constexpr int statistics = 8;  // per rank: the entries of `mine` in report()

template <int D>
void report(const sph::parallel::Communicator& ranks, const std::filesystem::path& caseDirectory, double wallWeight) {
    using namespace sph;
    const Dictionary controlDict = readCaseDictionary(caseDirectory, "system/controlDict");
    const TimeDirectory start = selectStartTime(caseDirectory, controlDict);
    CaseSetup<D> setup = parallel::setUpShareOfCase<D>(ranks, caseDirectory, start);
    FluidSystem<D>& system = *setup.system;
    const parallel::DistributedSystem<D> shared(ranks, system, wallWeight);
    const std::size_t bytesBefore = shared.haloBytesSent(), messagesBefore = shared.haloMessagesSent();
    system.evaluateRates(setup.header.time);
    const double width = shared.haloWidth();

    const std::size_t memory =
        system.fluid.size() * bytesPerParticle(everyArray(system.fluid)) + system.walls.size() * bytesPerParticle(everyArray(system.walls));
    const std::array<double, statistics> mine{double(shared.ownedFluidCount()),
                                              double(shared.ownedWallCount()),
                                              double(system.fluid.size() - shared.ownedFluidCount()),
                                              double(system.walls.size() - shared.ownedWallCount()),
                                              double(shared.neighbourRanks().size()),
                                              double(shared.haloBytesSent() - bytesBefore),
                                              double(shared.haloMessagesSent() - messagesBefore),
                                              double(memory)};
    std::vector<double> all(static_cast<std::size_t>(statistics * ranks.size()));
    MPI_Gather(mine.data(), statistics, MPI_DOUBLE, all.data(), statistics, MPI_DOUBLE, 0, ranks.handle());
    const double imbalance = parallel::loadImbalance(ranks, shared.ownedWeight());
    if (ranks.rank() != 0) return;

    fmt::print("decompositionReport: {}, {}D, {} rank{}, halo width {:.6g} m (support radius {:.6g}), wall weight {:g}\n", caseName(caseDirectory), D,
               ranks.size(), ranks.size() == 1 ? "" : "s", width, system.supportRadius(), wallWeight);
    fmt::print("{:>5} {:>10} {:>10} {:>11} {:>10} {:>11} {:>11} {:>12} {:>9} {:>12}\n", "rank", "fluid", "walls", "fluid halo", "wall halo",
               "halo/owned", "neighbours", "bytes sent", "messages", "memory MiB");
    std::array<double, statistics> total{}, largest{};
    for (int r = 0; r < ranks.size(); ++r) {
        const double* row = &all[static_cast<std::size_t>(r * statistics)];
        const double owned = row[0] + row[1], halo = row[2] + row[3];
        fmt::print("{:>5} {:>10} {:>10} {:>11} {:>10} {:>10.1f}% {:>11} {:>12} {:>9} {:>12.2f}\n", r, row[0], row[1], row[2], row[3],
                   owned > 0 ? 100.0 * halo / owned : 0.0, row[4], row[5], row[6], row[7] / 1048576.0);
        for (int s = 0; s < statistics; ++s) total[s] += row[s], largest[s] = std::max(largest[s], row[s]);
    }
    const double owned = total[0] + total[1], halo = total[2] + total[3];
    fmt::print("total: {} fluid and {} wall particles owned, {} halo copies ({:.1f} % of the owned), {} messages and {} bytes per evaluation\n",
               total[0], total[1], halo, 100.0 * halo / owned, total[6], total[5]);
    fmt::print("load imbalance (largest / mean weight): {:.4f}; memory per rank: largest {:.2f} MiB, mean {:.2f} MiB\n", imbalance,
               largest[7] / 1048576.0, total[7] / ranks.size() / 1048576.0);
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
            const sph::TimeDirectory start = sph::selectStartTime(caseDirectory, sph::readCaseDictionary(caseDirectory, "system/controlDict"));
            const int dimension = sph::readStateHeader(sph::stateFile(start.path, "fluid")).dimension;
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
