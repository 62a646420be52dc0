// What a run writes into the case: each written time as <case>/<time>/fluid.vtu and walls.vtu
// (and .csv on request), written atomically with the restart state in their headers and listed
// in <case>/<case>.pvd; a -rates evaluation into postProcessing/rates/<time>/.
#pragma once

#include "driver/CaseDirectory.hpp"
#include "driver/FluidSetup.hpp"
#include "io/PvdCollection.hpp"

#include <filesystem>

namespace sph {

template <int D>
class CaseOutput {
public:
    // The .pvd lists the times the case already holds up to `start`, so a restarted run's
    // collection still opens as one series.
    CaseOutput(const std::filesystem::path& caseDirectory, const TimeDirectory& start, CaseSetup<D>& setup, bool writeCsv);

    void writeTime(double t, long step);
    // The state with the rates evaluated at it, and .csv files whatever writeCsv says.
    void writeRates(double t);

private:
    void writeState(const std::filesystem::path& directory, double t, long step);

    std::filesystem::path caseDirectory_;
    CaseSetup<D>& setup_;
    StateHeader header_;
    bool writeCsv_;
    PvdCollection pvd_;
};

}  // namespace sph
