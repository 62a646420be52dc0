// The driver: reads a case directory, assembles the selected models through their registries
// (echoing every selection), validates the input before the first step, runs the time loop,
// writes output and reports. Bad input is a FatalError before any step.
#pragma once

#include <filesystem>

namespace sph {

// Runs the case to its endTime. Throws FatalError for bad input or a run that blows up.
void runCase(const std::filesystem::path& caseDirectory);

}  // namespace sph
