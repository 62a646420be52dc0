// Function objects in a decomposed run, a first version: rank 0 holds the whole case a second
// time, and when an object is due every rank sends it its owned particles (every field); rank 0
// puts them in the serial order and executes the objects on them, so that each computes what it
// computes in the serial run, and writes its files as it does there. The price: rank 0 holds and
// receives the whole state at every execution (an object's reduction over the ranks, without
// the gather, is what issue 23 asks next).
#pragma once

#include "driver/CaseDirectory.hpp"
#include "driver/FluidSetup.hpp"
#include "driver/FunctionObjectSchedule.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedSystem.hpp"

#include <filesystem>
#include <optional>

namespace sph::parallel {

template <int D>
class GatheredFunctionObjects {
public:
    // Collective. Selects controlDict's `functions` on rank 0, which reads the case again for
    // them; FatalError on every rank for a bad entry. Nothing where controlDict has none.
    GatheredFunctionObjects(const Communicator& ranks, const std::filesystem::path& caseDirectory, const TimeDirectory& start,
                            const Dictionary& controlDict, double rho0);

    // Rank 0: whether an object is due at t; false on the others and without objects.
    bool dueAt(double t) const { return schedule_ && schedule_->dueAt(t); }

    // Collective: gathers the state to rank 0 and executes the objects due (every object when
    // `force`), where there are objects, with the patches' motions of `running` (rank 0's copy of
    // the case never moves: a free body's state and loads are the running one's).
    void execute(const DistributedSystem<D>& shared, FluidSystem<D>& running, double t, bool force);

    // Rank 0: the run's closing line of every error an object measured.
    void reportErrorAgainstCost(const std::filesystem::path& caseDirectory, double startTime, const RunCost& cost) const;

private:
    Communicator ranks_;
    bool any_ = false;                                   // the same on every rank
    std::optional<CaseSetup<D>> whole_;                  // rank 0
    std::optional<FunctionObjectSchedule<D>> schedule_;  // rank 0
};

}  // namespace sph::parallel
