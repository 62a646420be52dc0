// libFuzzer target: the state-file reader (the layout check, then VTK's XML reader) on any
// bytes. A FatalError is the expected end of bad input; any other exception, a crash, a hang
// or a sanitizer report is a finding. Built with -DSPHKIT_FUZZ=ON and clang (see doc/reliability.md).
#include "core/FatalError.hpp"
#include "io/ParticleFile.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // VTK reads files only: each input is written to this process's own file first, removed
    // when libFuzzer ends the process (exit() runs the static destructor).
    struct ScratchFile {
        std::filesystem::path path = std::filesystem::temp_directory_path() / ("sphkitFuzzState." + std::to_string(::getpid()) + ".vtu");
        ~ScratchFile() {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
    };
    static const ScratchFile scratch;
    const std::string file = scratch.path.string();
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    for (int dimension = 2; dimension <= 3; ++dimension) {
        try {
            sph::StateHeader header;
            if (dimension == 2)
                (void)sph::readParticleFile<2>(file, "fluid", header);
            else
                (void)sph::readParticleFile<3>(file, "fluid", header);
        } catch (const sph::FatalError&) {
        }
    }
    return 0;
}
