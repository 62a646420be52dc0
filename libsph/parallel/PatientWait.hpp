// Waiting for MPI requests without holding a core, where the ranks outnumber the cores. MPI's
// own waits poll until the message is there (OpenMPI yields between polls when it knows the
// ranks outnumber the cores, and that is all). On a node with more ranks than cores (a laptop,
// tests that run 3 or 4 ranks on 2 cores) the polling ranks take the time slices of the rank
// they wait for, the more so beside other work: with one busy process beside it, a 2D dam break
// on 3 ranks of 2 cores ran 7 times slower than alone. A patient wait polls for 50 us, then
// sleeps between polls for an eighth of the time waited so far (5 us to 200 us), and leaves the
// core to whoever has work. With a core per rank the ranks poll, as MPI does: there sleeping
// made the waits longer (2D benchmark dam break on 2 ranks: +10 %).
#pragma once
#include <mpi.h>

#include <span>

namespace sph::parallel {

// Whether this node runs more ranks (OpenMPI's OMPI_COMM_WORLD_LOCAL_SIZE) than it has cores.
bool ranksOutnumberCores();

void waitPatiently(std::span<MPI_Request> requests);

}  // namespace sph::parallel
