// wcsph -parallel -rates: the right-hand side at the start time on the ranks mpirun starts. Each
// rank takes the particles its RCB box holds and copies of those within the kernel support of
// it, evaluates the rates of all of them and writes those of its own, in pieces, to
// postProcessing/rates/<time>/ (fluid.pvtu, walls.pvtu; doc/fileFormats.md).
// With one thread per rank the rates equal the serial -rates bit for bit: a rank's particles
// keep the serial order (that of the state files), and the cell lists have the serial grid, so
// an owned particle meets its neighbours, and adds their terms, in the serial order.
// So far (issue 23): fixed dynamicBoundary and dummyParticles walls, continuity or summation
// density, periodic directions, any kernel and viscosity, the density diffusions without a
// density gradient. Anything else stops
// before the evaluation, naming what does not run on several ranks yet. Every rank reads the
// whole case (pieces per rank come with the time loop).
#pragma once

#include "parallel/Communicator.hpp"

#include <filesystem>
#include <optional>

namespace sph::parallel {

// Collective. FatalError on every rank for anything the serial -rates rejects, and for what
// does not run on several ranks yet.
void writeRatesInParallel(const Communicator& ranks, const std::filesystem::path& caseDirectory, std::optional<int> threads);

}  // namespace sph::parallel
