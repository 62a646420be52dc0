#include "driver/Progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

namespace sph {

Progress::Progress(double startTime, double endTime, std::size_t particles)
    : startTime_(startTime),
      endTime_(endTime),
      particles_(particles),
      terminal_(::isatty(STDOUT_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_) {}

double Progress::elapsedSeconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

void Progress::update(long step, double t, double dt) {
    const auto now = std::chrono::steady_clock::now();
    const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
    if (sinceLast < (terminal_ ? 0.25 : 10.0)) return;
    lastPrint_ = now;
    const double wall = elapsedSeconds();
    const double fraction = (t - startTime_) / (endTime_ - startTime_);
    const double eta = fraction > 0.0 ? wall * (1.0 - fraction) / fraction : 0.0;
    const std::string line =
        fmt::format("step {:>8}  t = {:<11.6g} dt = {:<10.4g} particles {}  wall {:.1f} s  ETA {:.1f} s", step, t, dt, particles_, wall, eta);
    if (terminal_) {
        fmt::print("\r{}\x1b[K", line);
        std::fflush(stdout);
        printedInPlace_ = true;
    } else {
        fmt::print("{}\n", line);
        std::fflush(stdout);
    }
}

void Progress::finish() {
    if (printedInPlace_) fmt::print("\n");
    printedInPlace_ = false;
}

}  // namespace sph
