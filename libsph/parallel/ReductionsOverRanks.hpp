// The function objects' reductions (functionObjects/Reductions.hpp) over the ranks of a
// decomposed run: exact sums as integer sums of their bins, extrema and gathers by MPI's
// collectives; rank 0 writes the objects' files.
#pragma once

#include "functionObjects/Reductions.hpp"
#include "parallel/Communicator.hpp"

namespace sph::parallel {

class ReductionsOverRanks : public Reductions {
public:
    explicit ReductionsOverRanks(const Communicator& ranks) : ranks_(ranks) {}

    bool writesFiles() const override { return ranks_.rank() == 0; }
    void sum(std::span<ExactSum> sums) const override;
    void max(std::span<double> values) const override { ranks_.maxOverRanks(values); }
    std::vector<double> gather(std::span<const double> mine) const override { return ranks_.gatherToAll(mine); }
    void together(const std::function<void()>& body) const override { parallel::together(ranks_, body); }

private:
    Communicator ranks_;
};

}  // namespace sph::parallel
