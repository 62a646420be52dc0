// The threads a run uses (driver/Threads.hpp): the count from the particles, and the bounded
// spin that wcsph sets for itself before libgomp starts.
#include "driver/Threads.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstdio>
#include <string>

namespace {

// What `wcsph -help` prints to both streams under `environment` (an env(1) argument list).
std::string wcsphHelpWith(const std::string& environment) {
    const std::string command = "env " + environment + " " SPHKIT_WCSPH_EXECUTABLE " -help 2>&1";
    std::string output;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return output;
    char buffer[4096];
    while (const std::size_t read = fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, read);
    pclose(pipe);
    return output;
}

}  // namespace

TEST(Threads, OnePerThreeThousandParticlesIn2DAndPerEightHundredIn3DWithinWhatOpenMPOffers) {
    EXPECT_EQ(sph::threadsForParticles(0, 2, 2), 1);
    EXPECT_EQ(sph::threadsForParticles(5999, 2, 2), 1);
    EXPECT_EQ(sph::threadsForParticles(6000, 2, 2), 2);
    EXPECT_EQ(sph::threadsForParticles(2'000'000, 2, 2), 2);
    EXPECT_EQ(sph::threadsForParticles(20'000, 2, 16), 6);
    EXPECT_EQ(sph::threadsForParticles(20'000, 2, 0), 1);
    EXPECT_EQ(sph::threadsForParticles(5999, 1, 2), 1);
    EXPECT_EQ(sph::threadsForParticles(1599, 3, 2), 1);
    EXPECT_EQ(sph::threadsForParticles(1600, 3, 2), 2);
    EXPECT_EQ(sph::threadsForParticles(20'000, 3, 16), 16);
}

TEST(Threads, ARunSetsItsCountAndRestoresTheOneBefore) {
    const int before = omp_get_max_threads();
    {
        const sph::RunThreads small(100, 2, std::nullopt);
        EXPECT_EQ(omp_get_max_threads(), 1);
    }
    EXPECT_EQ(omp_get_max_threads(), before);
    {
        const sph::RunThreads requested(100, 2, 3);
        EXPECT_EQ(omp_get_max_threads(), 3);
        int team = 0;
#pragma omp parallel
#pragma omp single
        team = omp_get_num_threads();
        EXPECT_EQ(team, 3);
    }
    EXPECT_EQ(omp_get_max_threads(), before);
}

TEST(Threads, WcsphBoundsTheSpinOfWaitingThreads) {
    // libgomp prints its settings as it loads: once in the first start, once in the second.
    const std::string output = wcsphHelpWith("-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT OMP_DISPLAY_ENV=verbose");
    EXPECT_NE(output.find("GOMP_SPINCOUNT = '300'"), std::string::npos) << output;
}

TEST(Threads, AWaitPolicyTheUserChoseIsKept) {
    const std::string spin = wcsphHelpWith("-u OMP_WAIT_POLICY GOMP_SPINCOUNT=1234 OMP_DISPLAY_ENV=verbose");
    EXPECT_NE(spin.find("GOMP_SPINCOUNT = '1234'"), std::string::npos) << spin;
    EXPECT_EQ(spin.find("GOMP_SPINCOUNT = '300'"), std::string::npos) << spin;
    const std::string passive = wcsphHelpWith("-u GOMP_SPINCOUNT OMP_WAIT_POLICY=passive OMP_DISPLAY_ENV=verbose");
    EXPECT_EQ(passive.find("GOMP_SPINCOUNT = '300'"), std::string::npos) << passive;
}
