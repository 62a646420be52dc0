// wcsph -parallel: a case run on the ranks mpirun starts, each rank with its share of the
// particles (DistributedSystem) and OpenMP within it. With one thread per rank the run equals the
// serial run bit for bit: the time step, the states written and the rates (-rates).
//
// One decision per step, taken together (a maximum over the ranks of a few numbers): the next
// step's size, whether a rank found a blown-up particle, a stop signal, whether a function object
// is due (every rank executes it on its share, combining over the ranks: ReductionsOverRanks;
// rank 0 writes its files), the displacement
// that calls for new halos before the next cell sort, and rank 0's reading of a changed
// controlDict. Output: <time>/fluid.pvtu and walls.pvtu with one piece per rank
// (fluid_<r>.vtu, ...), listed in the case's .pvd; -rates writes the same to
// postProcessing/rates/<time>/. A run restarts from pieces or a serial state, on any number of
// ranks (io/ParticleState).
// Every integrator: the native ones, and the SUNDIALS ones on an MPI ManyVector of the owned
// particles (StateOverRanks; they restart where the serial run restarts, and take a rank's new
// particles after a migration: arkodeERK by ARKODE's resize, the others by a restart); every
// boundary model, walls fixed, with a prescribed motion or free bodies (halos as wide as
// BoundaryModel::reach; a free body's loads summed in the serial order); continuity or summation
// density; periodic directions; any kernel, viscosity and density diffusion; particle shifting.
// Each rank reads and sets up a share of the start state (ShareOfCase): no rank holds the whole
// of it, at the start or later. The boxes
// are made again when the ranks' measured work drifts apart (CostBalance).
#pragma once

#include "driver/Simulation.hpp"
#include "parallel/Communicator.hpp"

#include <filesystem>
#include <optional>

namespace sph::parallel {

// Collective. FatalError on every rank for what the serial run rejects, what does not run on
// several ranks yet, and a blow-up.
void runCaseInParallel(const Communicator& ranks, const std::filesystem::path& caseDirectory, RunMode mode, bool overwriteLaterTimes,
                       std::optional<int> threads, double balanceThreshold);

}  // namespace sph::parallel
