// The main() of a program started by mpirun: MPI set up and shut down around `body`, which
// every rank runs. Errors are collective (every rank stops with the same message): rank 0 alone
// prints them, as it alone prints to stdout (the others' goes to /dev/null). Returns the exit
// status: 0, 1 for a FatalError, as core/ExitOnError's exitCodeOf.
#pragma once

#include "parallel/Communicator.hpp"

#include <functional>

namespace sph::parallel {

int runOnRanks(const std::function<void(const Communicator& ranks)>& body);

}  // namespace sph::parallel
