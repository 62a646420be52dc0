// The patient wait (parallel/PatientWait.hpp): a rank that waits for a message leaves its core,
// and it waits so only where the ranks outnumber the cores.
#include "parallel/PatientWait.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <string>
#include <thread>

namespace sph::parallel {
namespace {

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

TEST(PatientWait, ARankWaitingForAMessageLeavesItsCore) {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size < 2) GTEST_SKIP() << "needs two ranks";
    constexpr auto sendersDelay = std::chrono::milliseconds(200);
    int message = 0;
    if (rank == 1) {
        std::this_thread::sleep_for(sendersDelay);
        message = 42;
        MPI_Send(&message, 1, MPI_INT, 0, 7, MPI_COMM_WORLD);
    }
    if (rank != 0) return;
    MPI_Request request;
    MPI_Irecv(&message, 1, MPI_INT, 1, 7, MPI_COMM_WORLD, &request);
    const double cpuBefore = threadCpuSeconds();
    const auto wallBefore = std::chrono::steady_clock::now();
    waitPatiently(std::span<MPI_Request>(&request, 1));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallBefore).count();
    const double cpu = threadCpuSeconds() - cpuBefore;
    EXPECT_EQ(message, 42);
    EXPECT_GT(wall, 0.1);
    // Polling, as MPI_Wait does, would take the whole wait on the processor.
    EXPECT_LT(cpu, 0.25 * wall) << "the waiting rank used " << cpu << " s of processor in " << wall << " s";
}

TEST(PatientWait, OnlyWhereTheNodesRanksOutnumberItsCores) {
    const char* name = "OMPI_COMM_WORLD_LOCAL_SIZE";
    const char* launched = std::getenv(name);
    const std::string kept = launched ? launched : "";
    const unsigned cores = std::thread::hardware_concurrency();
    setenv(name, std::to_string(cores + 1).c_str(), 1);
    EXPECT_TRUE(ranksOutnumberCores());
    setenv(name, std::to_string(cores).c_str(), 1);
    EXPECT_FALSE(ranksOutnumberCores());
    unsetenv(name);
    EXPECT_FALSE(ranksOutnumberCores()) << "not started by OpenMPI: MPI's own wait";
    if (launched) setenv(name, kept.c_str(), 1);
}

}  // namespace
}  // namespace sph::parallel
