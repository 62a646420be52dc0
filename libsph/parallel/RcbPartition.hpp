// Recursive coordinate bisection by Zoltan (Trilinos): cuts space, the longest direction first,
// so that each rank's box holds an equal share of the weight of all ranks' points. Only the cuts
// are taken from Zoltan; which particle goes where follows from the boxes (DomainBoxes).
//   Zoltan parameters: LB_METHOD RCB, KEEP_CUTS 1 (every rank can ask for every box),
//   RCB_RECTILINEAR_BLOCKS 1, AVERAGE_CUTS 1 (a cut midway between lattice columns, not through
//   one), RETURN_LISTS NONE.
#pragma once

#include "parallel/Communicator.hpp"
#include "parallel/DomainBoxes.hpp"

#include <span>

namespace sph::parallel {

// Collective. `points` and `weights` (one each, positive) are this rank's; a rank may have none.
// `lower`/`upper` bound the domain and `period` is its length in each periodic direction (else 0).
template <int D>
DomainBoxes<D> partitionByRcb(const Communicator& ranks, std::span<const Vec<D>> points, std::span<const double> weights, const Vec<D>& lower,
                              const Vec<D>& upper, const Vec<D>& period);

// max / mean of the ranks' weights: 1 for a perfect balance (and where no rank has any weight).
double loadImbalance(const Communicator& ranks, double localWeight);

}  // namespace sph::parallel
