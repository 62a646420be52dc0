// generateParticles: writes a case's initial particle state 0/ from system/generateParticlesDict.
#include "core/ExitOnError.hpp"
#include "generation/ParticleGenerator.hpp"

#include <fmt/format.h>

#include <string>

namespace {

constexpr const char* usage = R"(Usage: generateParticles [OPTIONS]

Writes the initial state 0/fluid.vtu and 0/walls.vtu of a case from
system/generateParticlesDict (fluid regions, wall patches) and constant/fluidProperties.

Options:
  -case <dir>   case directory (default: the current directory)
  -overwrite    replace an existing 0/
  -help         print this message
)";

}  // namespace

int main(int argc, char** argv) {
    std::string caseDirectory = ".";
    bool overwrite = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "-help" || arg == "--help" || arg == "-h") {
            fmt::print("{}", usage);
            return 0;
        }
        if (arg == "-overwrite") {
            overwrite = true;
        } else if (arg == "-case" && i + 1 < argc) {
            caseDirectory = argv[++i];
        } else {
            fmt::print(stderr, "error: unknown or incomplete option '{}'\n\n{}", arg, usage);
            return 2;
        }
    }
    return sph::exitCodeOf([&] {
        const sph::GenerationSummary summary = sph::generateParticles(caseDirectory, overwrite);
        fmt::print("generateParticles: {}D, {} fluid particles, {} wall particles written to {}/0/", summary.dimension, summary.fluidParticles,
                   summary.wallParticles, caseDirectory);
        if (summary.droppedFluidParticles > 0) fmt::print(" ({} fluid particles overlapping walls dropped)", summary.droppedFluidParticles);
        fmt::print("\n");
        for (const std::string& note : summary.notes) fmt::print("note: {}\n", note);
        for (const std::string& warning : summary.warnings) fmt::print("warning: {}\n", warning);
    });
}
