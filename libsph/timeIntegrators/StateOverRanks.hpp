// What the SUNDIALS integrators need of a state shared over ranks (parallel/DistributedSystem).
// A rank holds its own particles and copies of its neighbours', mixed in the serial order; its
// part of the SUNDIALS vector holds the particles it owns only, and the parts of all ranks are
// one MPI ManyVector, whose norms and dot products SUNDIALS takes over every rank. The copies
// take their owners' state before each evaluation. A serial run has none of this: its vector
// wraps the particle arrays themselves.
#pragma once

#include <sundials/sundials_context.h>
#include <sundials/sundials_nvector.h>

#include <functional>
#include <string>
#include <vector>

namespace sph {

struct StateOverRanks {
    // Per particle held: 1 where this rank owns it.
    const std::vector<char>* fluidOwned = nullptr;
    const std::vector<char>* wallsOwned = nullptr;
    // Collective: the owners' fluid positions and velocities, and every density the integrator
    // advances, to their copies.
    std::function<void()> refreshCopies;
    // Collective: true on every rank where it is true on one.
    std::function<bool(bool)> onAnyRank;
    // Collective: this rank's subvectors joined with the other ranks' into one MPI ManyVector.
    std::function<N_Vector(std::vector<N_Vector>&, SUNContext)> join;
    // A subvector's values in a vector `join` made, or in a clone of one.
    double* (*subvectorData)(N_Vector, sunindextype) = nullptr;
    // Stops every rank with the message: a failure inside an evaluation that SUNDIALS called
    // cannot unwind through SUNDIALS' C frames, and the other ranks wait in that evaluation's
    // exchanges.
    std::function<void(const std::string&)> stopAll;
};

}  // namespace sph
