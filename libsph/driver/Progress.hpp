// Progress on the console: one line updated in place on a terminal, plain lines every few
// seconds otherwise (CI, log files).
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace sph {

class Progress {
public:
    Progress(double startTime, double endTime, std::size_t particles);
    void update(long step, double t, double dt);
    void finish();  // ends the in-place line
    void setEndTime(double endTime) { endTime_ = endTime; }
    double elapsedSeconds() const;

private:
    double startTime_, endTime_;
    std::size_t particles_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_, lastPrint_;
    bool printedInPlace_ = false;
};

}  // namespace sph
