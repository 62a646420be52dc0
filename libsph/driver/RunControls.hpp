// The run-control entries of system/controlDict, and their re-reading while the case runs:
// with `runTimeModifiable yes` (the default, as in OpenFOAM) a change of endTime or
// writeInterval takes effect at the next step. A bad new value is reported and ignored: the
// run goes on with the values it had.
#pragma once

#include "io/Dictionary.hpp"

#include <filesystem>
#include <optional>

namespace sph {

struct RunControls {
    double endTime = 0.0;
    double writeInterval = 0.0;

    // FatalError naming the keyword for a missing or bad value.
    static RunControls read(const Dictionary& controlDict);

    // Write times are whole multiples of writeInterval, computed afresh rather than
    // accumulated, so a restarted run writes (and lands its steps) where the uninterrupted one did.
    double nextWriteAfter(double t) const;
};

class ControlDictWatcher {
public:
    ControlDictWatcher(std::filesystem::path file, bool enabled);

    // The controls re-read from the file if it changed since the last call and they differ.
    std::optional<RunControls> changed(const RunControls& current, double t);

private:
    std::filesystem::path file_;
    bool enabled_;
    std::filesystem::file_time_type lastWrite_;
    std::uintmax_t lastSize_ = 0;
};

}  // namespace sph
