// generateParticles: writes a case's initial particle state 0/ from system/generateParticlesDict.
#include "core/ExitOnError.hpp"
#include "generation/ParticleGenerator.hpp"

#ifdef SPHKIT_WITH_MPI
#include "parallel/RunOnRanks.hpp"
#endif

#include <fmt/format.h>

#include <string>

namespace {

constexpr const char* usage = R"(Usage: generateParticles [OPTIONS]

Writes the initial state 0/fluid.vtu and 0/walls.vtu of a case from
system/generateParticlesDict (fluid regions, wall patches) and constant/fluidProperties.

Options:
  -case <dir>   case directory (default: the current directory)
  -overwrite    replace an existing 0/
  -parallel     under mpirun (builds with MPI): each of the N ranks fills its rows of every
                fluid region and writes them as a piece of 0/fluid.pvtu, and a block of the
                walls as a piece of 0/walls.pvtu; no rank holds the whole fluid. The pieces
                carry the serial order: a run from them equals a run from the serial state
  -help         print this message
)";

void printSummary(const sph::GenerationSummary& summary, const std::string& caseDirectory, const char* form) {
    fmt::print("generateParticles: {}D, {} fluid particles, {} wall particles written to {}/0/{}", summary.dimension, summary.fluidParticles,
               summary.wallParticles, caseDirectory, form);
    if (summary.droppedFluidParticles > 0) fmt::print(" ({} fluid particles overlapping walls dropped)", summary.droppedFluidParticles);
    fmt::print("\n");
    for (const std::string& note : summary.notes) fmt::print("note: {}\n", note);
    for (const std::string& warning : summary.warnings) fmt::print("warning: {}\n", warning);
}

#ifdef SPHKIT_WITH_MPI
int generateInParallel(const std::string& caseDirectory, bool overwrite) {
    return sph::parallel::runOnRanks([&](const sph::parallel::Communicator& ranks) {
        const sph::GenerationShare share{{ranks.rank(), ranks.size()},
                                         [&](std::span<const double> mine) { return ranks.gatherToAll(mine); },
                                         [&](const std::function<void()>& body) { sph::parallel::together(ranks, body); }};
        const sph::GenerationSummary summary = sph::generateParticles(caseDirectory, overwrite, &share);
        printSummary(summary, caseDirectory, fmt::format(" in {} pieces", share.rows.count).c_str());
    });
}
#endif

}  // namespace

int main(int argc, char** argv) {
    std::string caseDirectory = ".";
    bool overwrite = false;
    bool parallel = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-help" || arg == "--help" || arg == "-h") {
            fmt::print("{}", usage);
            return 0;
        }
        if (arg == "-overwrite") {
            overwrite = true;
        } else if (arg == "-parallel") {
            parallel = true;
        } else if (arg == "-case" && i + 1 < argc) {
            caseDirectory = argv[++i];
        } else {
            fmt::print(stderr, "error: unknown or incomplete option '{}'\n\n{}", arg, usage);
            return 2;
        }
    }
    if (parallel) {
#ifdef SPHKIT_WITH_MPI
        return generateInParallel(caseDirectory, overwrite);
#else
        fmt::print(stderr,
                   "error: -parallel needs a build with MPI (CMake SPHKIT_MPI; packages openmpi-bin libopenmpi-dev libtrilinos-zoltan-dev)\n");
        return 2;
#endif
    }
    return sph::exitCodeOf([&] { printSummary(sph::generateParticles(caseDirectory, overwrite), caseDirectory, ""); });
}
