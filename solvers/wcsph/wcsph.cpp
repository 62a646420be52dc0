// wcsph: the weakly compressible SPH solver. Runs the case directory given by -case (default:
// the current directory) from its start time to endTime.
#include "driver/ModelCatalogue.hpp"
#include "driver/Simulation.hpp"
#include "core/ExitOnError.hpp"
#include "driver/FreedMemory.hpp"
#include "driver/Threads.hpp"

#include <fmt/format.h>

#ifdef SPHKIT_WITH_MPI
#include "parallel/CostBalance.hpp"
#include "parallel/ParallelRun.hpp"
#include "parallel/RunOnRanks.hpp"

#include <mpi.h>
#endif

#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace {

constexpr const char* usage = R"(Usage: wcsph [OPTIONS]

Weakly compressible SPH solver: runs an OpenFOAM-style case directory from its start time
(system/controlDict startFrom) to endTime, writing <time>/fluid.vtu, <time>/walls.vtu and a
<case>.pvd collection that ParaView opens.

Options:
  -case <dir>     case directory (default: the current directory)
  -listModels [FAMILY]
                  list every selectable model with its coefficients, defaults and reference;
                  FAMILY (kernel, density, viscosity, densityDiffusion, equationOfState,
                  boundary, motion, integrator, functionObject, analytic) lists that one only
  -rates          evaluate the right-hand side once at the start time (accelerations, density
                  rates, boundary corrections) and write it to postProcessing/rates/<time>/
                  as .vtu and .csv
  -overwrite      with startFrom startTime: remove the times after the start time that an
                  earlier run wrote (without it the solver refuses to overwrite them)
  -threads <N>    run on N threads (default: one per 3,000 particles, per 800 in 3D, at most
                  OMP_NUM_THREADS or the cores)
  -parallel       under mpirun (builds with MPI): share the case among the ranks, each
                  writing its piece of every state (<time>/fluid.pvtu); so far with the native
                  integrators and dynamicBoundary, dummyParticles or deficiencyCorrection walls,
                  fixed or moving, without free bodies (doc/userGuide.md)
  -balance <R>    with -parallel: new boxes at a cell sort when the slowest rank's work since
                  the last partition passes R times the mean (checked every 100 steps; default
                  1.1; 0: keep the first partition)
  -help           print this message

Before the first run, generateParticles writes the initial state 0/ from
system/generateParticlesDict. Ctrl-C or SIGTERM finishes the current step, writes the state
and exits; running again continues from the latest written time (startFrom latestTime).
Unless OMP_WAIT_POLICY or GOMP_SPINCOUNT is set, the solver starts itself again with
GOMP_SPINCOUNT=300, so that a thread waiting for another does not take the core it needs on a
shared machine (doc/performance.md).
See doc/userGuide.md and doc/reliability.md.
)";

// The whole of `text` as a number, or nothing.
template <class Number>
std::optional<Number> parseNumber(const std::string& text) {
    std::size_t used = 0;
    Number value{};
    try {
        if constexpr (std::is_integral_v<Number>)
            value = std::stoi(text, &used);
        else
            value = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (used != text.size()) return std::nullopt;
    return value;
}

// 0 or a ratio of at least 1, or nothing.
std::optional<double> parseBalanceThreshold(const std::string& text) {
    const std::optional<double> threshold = parseNumber<double>(text);
    if (!threshold || !(*threshold == 0.0 || (*threshold >= 1.0 && *threshold < 1e6))) return std::nullopt;
    return threshold;
}

// A whole number of threads from 1 to 4096, or nothing.
std::optional<int> parseThreadCount(const std::string& text) {
    const std::optional<int> threads = parseNumber<int>(text);
    if (!threads || *threads < 1 || *threads > 4096) return std::nullopt;
    return threads;
}

#ifdef SPHKIT_WITH_MPI
int runInParallel(const std::string& caseDirectory, sph::RunMode mode, bool overwrite, std::optional<int> threads, double balanceThreshold) {
    return sph::parallel::runOnRanks([&](const sph::parallel::Communicator& ranks) {
        sph::parallel::runCaseInParallel(ranks, caseDirectory, mode, overwrite, threads, balanceThreshold);
    });
}
#endif

}  // namespace

int main(int argc, char** argv) {
    sph::boundSpinWaiting(argv);
    sph::keepFreedMemoryForReuse();
    std::string caseDirectory = ".";
    sph::RunMode mode = sph::RunMode::TimeLoop;
    bool overwrite = false;
    bool parallel = false;
    std::optional<int> threads;
    std::optional<double> balanceThreshold;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-help" || arg == "--help" || arg == "-h") {
            fmt::print("{}", usage);
            return 0;
        }
        if (arg == "-listModels") {
            const std::string family = i + 1 < argc && argv[i + 1][0] != '-' ? argv[i + 1] : "";
            try {
                fmt::print("{}", sph::modelCatalogue(family));
            } catch (const std::invalid_argument& e) {
                fmt::print(stderr, "error: {}\n", e.what());
                return 2;
            }
            return 0;
        }
        if (arg == "-rates") {
            mode = sph::RunMode::RatesOnly;
            continue;
        }
        if (arg == "-overwrite") {
            overwrite = true;
            continue;
        }
        if (arg == "-parallel") {
            parallel = true;
            continue;
        }
        if (arg == "-threads" && i + 1 < argc) {
            threads = parseThreadCount(argv[++i]);
            if (!threads) {
                fmt::print(stderr, "error: -threads takes a whole number from 1 to 4096, found '{}'\n", argv[i]);
                return 2;
            }
            continue;
        }
        if (arg == "-balance" && i + 1 < argc) {
            balanceThreshold = parseBalanceThreshold(argv[++i]);
            if (!balanceThreshold) {
                fmt::print(stderr, "error: -balance takes 0 (keep the first partition) or a ratio of at least 1, found '{}'\n", argv[i]);
                return 2;
            }
            continue;
        }
        if (arg == "-case" && i + 1 < argc) {
            caseDirectory = argv[++i];
            continue;
        }
        fmt::print(stderr, "error: unknown or incomplete option '{}'\n\n{}", arg, usage);
        return 2;
    }
    if (balanceThreshold && !parallel) {
        fmt::print(stderr, "error: -balance applies to a run on several ranks (wcsph -parallel under mpirun)\n");
        return 2;
    }
    if (parallel) {
#ifdef SPHKIT_WITH_MPI
        return runInParallel(caseDirectory, mode, overwrite, threads, balanceThreshold.value_or(sph::parallel::CostBalance::defaultThreshold));
#else
        fmt::print(stderr,
                   "error: -parallel needs a build with MPI (CMake SPHKIT_MPI; packages openmpi-bin libopenmpi-dev libtrilinos-zoltan-dev)\n");
        return 2;
#endif
    }
    return sph::exitCodeOf([&] { sph::runCase(caseDirectory, mode, overwrite, threads); });
}
