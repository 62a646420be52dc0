#include "parallel/PatientWait.hpp"

#include <sys/prctl.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <thread>

namespace sph::parallel {

bool ranksOutnumberCores() {
    const char* ranksOnNode = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    return ranksOnNode && std::strtoul(ranksOnNode, nullptr, 10) > std::thread::hardware_concurrency();
}

void waitPatiently(std::span<MPI_Request> requests) {
    using namespace std::chrono_literals;
    using Clock = std::chrono::steady_clock;
    constexpr auto polling = 50us, shortestSleep = 5us, longestSleep = 200us;
    // Linux wakes a sleeping thread up to 50 us late by default (timer slack): 1 us instead, so
    // that a sleep overshoots what it was asked by little more than the scheduler's latency.
    [[maybe_unused]] static const bool precise = prctl(PR_SET_TIMERSLACK, 1000UL) == 0;
    const Clock::time_point start = Clock::now();
    for (;;) {
        int done = 0;
        MPI_Testall(static_cast<int>(requests.size()), requests.data(), &done, MPI_STATUSES_IGNORE);
        if (done) return;
        const auto waited = std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
        if (waited < polling) continue;
        // An eighth of the wait so far: a late wake-up costs at most an eighth of the wait.
        std::this_thread::sleep_for(std::clamp<std::chrono::microseconds>(waited / 8, shortestSleep, longestSleep));
    }
}

}  // namespace sph::parallel
