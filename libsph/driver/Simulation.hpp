// The driver: reads a case directory, assembles the selected models through their registries
// (echoing every selection), validates the input before the first step, runs the time loop,
// writes output and reports. Bad input is a FatalError before any step.
#pragma once

#include "driver/CaseDirectory.hpp"
#include "io/Dictionary.hpp"

#include <filesystem>
#include <optional>

namespace sph {

enum class RunMode {
    TimeLoop,   // from the start time to endTime
    RatesOnly,  // evaluate the right-hand side once at the start time and write it to postProcessing/rates/<time>/
};

// Reordering the fluid by cell costs a pass over every field; particles move little per step.
// The sorts fall on the steps that are multiples of this, counted from the run's first step, so
// that a restarted run sorts where the uninterrupted one did.
constexpr long stepsBetweenCellSorts = 10;

// system/controlDict of an existing case directory, or FatalError.
Dictionary readControlDict(const std::filesystem::path& caseDirectory);

// Removes what an interrupted write left (TimeLoop), selects the start time, and with times
// later than it, stops (FatalError) or, with `overwriteLaterTimes`, removes them.
TimeDirectory prepareStartTime(const std::filesystem::path& caseDirectory, const Dictionary& controlDict, RunMode mode, bool overwriteLaterTimes);

// Runs the case. Throws FatalError for bad input or a run that blows up, and when times later
// than the start time exist (startFrom startTime): the run would overwrite them, unless
// `overwriteLaterTimes` (wcsph -overwrite), which removes them first. `threads` (wcsph -threads)
// replaces the rule of driver/Threads.hpp.
void runCase(const std::filesystem::path& caseDirectory, RunMode mode = RunMode::TimeLoop, bool overwriteLaterTimes = false,
             std::optional<int> threads = std::nullopt);

}  // namespace sph
