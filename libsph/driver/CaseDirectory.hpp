// The layout of a case directory, and the dictionaries the solver reads from it:
//   system/controlDict          run control and function objects
//   system/sphSchemes           kernel, density formulation, viscosity, density diffusion
//   system/timeIntegration      integrator, Courant number, step limits
//   constant/fluidProperties    rho0, equation of state, nu, gravity
//   constant/boundaryProperties one boundary model per wall patch
//   <time>/fluid.vtu, walls.vtu particle state at each written time (0/ from generateParticles);
//                               fluid.pvtu, walls.pvtu and their pieces from wcsph -parallel
#pragma once

#include "io/Dictionary.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace sph {

struct TimeDirectory {
    double time;
    std::filesystem::path path;
};

// The case's name: its directory's, also when given as "." or with a trailing slash.
std::string caseName(const std::filesystem::path& caseDirectory);

// Time directories holding a complete state (fluid.vtu or fluid.pvtu), in increasing time; those
// named as a time that hold neither are added to `withoutState` when given.
std::vector<TimeDirectory> findTimeDirectories(const std::filesystem::path& caseDirectory,
                                               std::vector<std::filesystem::path>* withoutState = nullptr);

// A written time's fluid and wall state files, relative to the case (as the .pvd lists them).
std::vector<std::string> stateFilesOf(const TimeDirectory& written);

// The time directories after `time`, in increasing time.
std::vector<TimeDirectory> timesAfter(const std::filesystem::path& caseDirectory, double time);

// Removes the given time directories, naming each on the console.
void removeTimeDirectories(const std::vector<TimeDirectory>& times);

// The time directory controlDict's startFrom/startTime selects (FatalError if there is none).
TimeDirectory selectStartTime(const std::filesystem::path& caseDirectory, const Dictionary& controlDict);

// Removes what a killed run left half-written (hidden temporaries ".<name>.tmp<pid>" and
// ".<name>.old<pid>" of the atomic writes, for a time directory or a .vtu, .pvd, .csv or
// .dat file, whose process <pid> no longer runs), naming each on the console.
void removeIncompleteOutput(const std::filesystem::path& caseDirectory);

// Reads <case>/<relative>, naming the case's file in every message.
Dictionary readCaseDictionary(const std::filesystem::path& caseDirectory, const std::string& relative);

}  // namespace sph
