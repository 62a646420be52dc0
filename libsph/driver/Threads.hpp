// The threads a run uses: how many, and how they wait at the end of a parallel region.
//
// Count: one thread per `particlesPerThread(D)` particles (fluid + wall), at least one and at
// most what OpenMP offers (OMP_NUM_THREADS, else the cores); `wcsph -threads N` sets it
// outright. Every parallel region costs a wake-up and a barrier whatever its size. In 2D below
// about 3,000 particles a thread, a second thread saves 6-11 % of a step on a quiet machine and
// costs 54-82 % beside a busy process (damBreak2D at 2,300 and 3,600 particles). A 3D particle
// has about 3.5x the neighbours: 2 threads took 1.15x the 1-thread time at 552 particles
// (hydrostaticTank3D, H/dx = 4) and 0.59x at 3,488 (cylinderTank3D, H/dx = 6; 1.11x beside a
// busy process), so 3D takes one thread per 800. doc/performance.md.
//
// Waiting: libgomp's threads spin for 300,000 turns at a barrier before they sleep. On a shared
// machine the spinning thread takes the core its late sibling needs, and a 2-thread run took
// 2.1-2.8x (a pinned busy process) and up to 12x (unpinned) the 1-thread time. A spin of 300
// turns brings that to 1.06-1.13x from 24,000 to 196,000 particles (1.34x at 7,000) and keeps
// the quiet machine's 2-thread times within the runs' spread. libgomp reads its settings once,
// when it loads, so the bound is set by starting the solver again with it.
#pragma once

#include <cstddef>
#include <optional>

namespace sph {

// Particles per thread in 1D and 2D, and in 3D.
constexpr std::size_t particlesPerThread(int dimension) { return dimension == 3 ? 800 : 3000; }
inline constexpr const char* boundedSpinCount = "300";

// clamp(particles / particlesPerThread(dimension), 1, available).
int threadsForParticles(std::size_t particles, int dimension, int available);

// Unless the user chose a wait policy (OMP_WAIT_POLICY or GOMP_SPINCOUNT set), sets
// GOMP_SPINCOUNT and replaces the process by the same program with the same arguments. Returns
// only if that was not needed or the exec failed (the run then waits as libgomp's default).
// Call first thing in main, before anything that a second start would repeat.
void boundSpinWaiting(char** argv);

// Sets OpenMP's thread count for a run of `particles` particles in `dimension` dimensions
// (`requested` if given, else threadsForParticles), says so on standard output, and restores the
// previous count when it goes out of scope (the tests run several cases in one process).
class RunThreads {
public:
    RunThreads(std::size_t particles, int dimension, std::optional<int> requested);
    ~RunThreads();
    RunThreads(const RunThreads&) = delete;
    RunThreads& operator=(const RunThreads&) = delete;

private:
    int previous_;
};

}  // namespace sph
