#include "driver/CaseOutput.hpp"

#include "driver/RestartState.hpp"
#include "io/AtomicFile.hpp"
#include "io/ParticleCsv.hpp"
#include "io/ParticleFile.hpp"
#include "io/TimeName.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
CaseOutput<D>::CaseOutput(const std::filesystem::path& caseDirectory, const TimeDirectory& start, CaseSetup<D>& setup, bool writeCsv)
    : caseDirectory_(caseDirectory),
      setup_(setup),
      header_(setup.header),
      writeCsv_(writeCsv),
      pvd_(caseDirectory / (caseName(caseDirectory) + ".pvd")) {
    for (const TimeDirectory& written : findTimeDirectories(caseDirectory))
        if (written.time <= start.time) pvd_.add(written.time, stateFilesOf(written));
}

template <int D>
void CaseOutput<D>::writeState(const std::filesystem::path& directory, double t, long step) {
    header_.time = t;
    header_.step = step;
    collectRestartState(*setup_.system, *setup_.integrator, setup_.integratorType, header_);
    StateHeader wallHeader = header_;
    wallHeader.patchNames = setup_.patchNames;
    wallHeader.patchLayers = setup_.patchLayers;
    writeParticleFile(directory / "fluid.vtu", setup_.system->fluid, header_);
    writeParticleFile(directory / "walls.vtu", setup_.system->walls, wallHeader);
}

template <int D>
void CaseOutput<D>::writeTime(double t, long step) {
    FluidSystem<D>& system = *setup_.system;
    auto timer = system.timers.time(Stage::Output);
    const std::string name = timeName(t);
    writeDirectoryAtomically(caseDirectory_ / name, [&](const std::filesystem::path& directory) {
        writeState(directory, t, step);
        if (writeCsv_) {
            writeParticleCsv(directory / "fluid.csv", system.fluid);
            writeParticleCsv(directory / "walls.csv", system.walls);
        }
    });
    pvd_.add(t, {name + "/fluid.vtu", name + "/walls.vtu"});
}

template <int D>
void CaseOutput<D>::writeRates(double t) {
    const FluidSystem<D>& system = *setup_.system;
    const auto directory = caseDirectory_ / "postProcessing" / "rates" / timeName(t);
    writeDirectoryAtomically(directory, [&](const std::filesystem::path& temporary) {
        writeState(temporary, t, header_.step);
        writeParticleCsv(temporary / "fluid.csv", system.fluid);
        writeParticleCsv(temporary / "walls.csv", system.walls);
    });
    fmt::print("\nWrote the right-hand side at t = {:g} to {}\n", t, directory.string());
}

#ifdef SPHKIT_HAS_1D
template class CaseOutput<1>;
#endif
#ifdef SPHKIT_HAS_2D
template class CaseOutput<2>;
#endif
#ifdef SPHKIT_HAS_3D
template class CaseOutput<3>;
#endif

}  // namespace sph
