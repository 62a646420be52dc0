// A decomposed run's particles whole on one rank, for what reads them whole: the function
// objects and the .csv files (writeCsv), which see what they see in a serial run.
#pragma once

#include "core/ParticleSet.hpp"
#include "parallel/Communicator.hpp"

namespace sph::parallel {

// Collective. Every rank's particles of `set` on rank 0, in the serial order; `set` is left
// empty elsewhere.
template <int D>
void gatherToFirst(const Communicator& ranks, ParticleSet<D>& set);

}  // namespace sph::parallel
