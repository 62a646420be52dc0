#include "driver/RunControls.hpp"

#include "core/FatalError.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

RunControls RunControls::read(const Dictionary& controlDict) {
    RunControls controls;
    controls.endTime = controlDict.get<double>("endTime");
    if (!std::isfinite(controls.endTime)) controlDict.fail("endTime", fmt::format("must be a finite time, found {:g}", controls.endTime));
    controls.writeInterval = controlDict.getPositive("writeInterval");
    return controls;
}

double RunControls::nextWriteAfter(double t) const {
    // The tolerance makes a time that landed on a write time count as that write time.
    const double written = std::floor(t / writeInterval + 1e-9);
    return (written + 1.0) * writeInterval;
}

ControlDictWatcher::ControlDictWatcher(std::filesystem::path file, bool enabled) : file_(std::move(file)), enabled_(enabled) {
    std::error_code ec;
    lastWrite_ = std::filesystem::last_write_time(file_, ec);
    lastSize_ = std::filesystem::file_size(file_, ec);
}

std::optional<RunControls> ControlDictWatcher::changed(const RunControls& current, double t) {
    if (!enabled_) return std::nullopt;
    std::error_code ec;
    const auto lastWrite = std::filesystem::last_write_time(file_, ec);
    if (ec) return std::nullopt;
    // The size too: an editor's write can truncate and refill the file within the clock's
    // tick, and a read between the two must not hide the finished edit.
    const std::uintmax_t size = std::filesystem::file_size(file_, ec);
    if (ec || (lastWrite == lastWrite_ && size == lastSize_)) return std::nullopt;
    lastWrite_ = lastWrite;
    lastSize_ = size;
    try {
        const RunControls controls = RunControls::read(Dictionary::fromFile(file_, "controlDict"));
        if (!(controls.endTime > t))
            throw FatalError(fmt::format("error: '{}': endTime {:g} is not later than the current time {:g}", file_.string(), controls.endTime, t));
        if (controls.endTime == current.endTime && controls.writeInterval == current.writeInterval) return std::nullopt;
        fmt::print("\nRe-read {} at t = {:g}: endTime {:g}, writeInterval {:g}\n", file_.string(), t, controls.endTime, controls.writeInterval);
        return controls;
    } catch (const FatalError& error) {
        fmt::print(stderr, "\nwarning: ignoring the changed {} (the run goes on with endTime {:g}, writeInterval {:g}):\n{}\n", file_.string(),
                   current.endTime, current.writeInterval, error.what());
        return std::nullopt;
    }
}

}  // namespace sph
