#include "driver/Threads.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>

namespace sph {

int threadsForParticles(std::size_t particles, int dimension, int available) {
    const auto byParticles = static_cast<long long>(particles / particlesPerThread(dimension));
    return static_cast<int>(std::clamp<long long>(byParticles, 1, std::max(1, available)));
}

void boundSpinWaiting(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
    if (setenv("GOMP_SPINCOUNT", boundedSpinCount, 1) != 0) return;
    execv("/proc/self/exe", argv);
}

RunThreads::RunThreads(std::size_t particles, int dimension, std::optional<int> requested) : previous_(omp_get_max_threads()) {
    const int threads = requested ? *requested : threadsForParticles(particles, dimension, previous_);
    omp_set_num_threads(threads);
    if (requested)
        fmt::print("Threads: {} (-threads)\n", threads);
    else
        fmt::print("Threads: {} of {} ({} particles, one thread per {} in {}D; wcsph -threads N to choose)\n", threads, previous_, particles,
                   particlesPerThread(dimension), dimension);
}

RunThreads::~RunThreads() { omp_set_num_threads(previous_); }

}  // namespace sph
