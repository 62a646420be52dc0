// Restores OpenMP's thread count when a test that varies it ends, also when an assertion
// returns early, so that later tests run with the count they expect.
#pragma once

#include <omp.h>

namespace sph::test {

struct RestoreThreadCount {
    int threads = omp_get_max_threads();
    RestoreThreadCount() = default;
    RestoreThreadCount(const RestoreThreadCount&) = delete;
    RestoreThreadCount& operator=(const RestoreThreadCount&) = delete;
    ~RestoreThreadCount() { omp_set_num_threads(threads); }
};

}  // namespace sph::test
