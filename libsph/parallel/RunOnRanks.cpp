#include "parallel/RunOnRanks.hpp"

#include "core/ExitOnError.hpp"

#include <cstdio>

namespace sph::parallel {

int runOnRanks(const std::function<void(const Communicator& ranks)>& body) {
    MPI_Init(nullptr, nullptr);
    int status = 0;
    {
        const Communicator ranks;
        if (ranks.rank() != 0 && !std::freopen("/dev/null", "w", stdout)) status = 3;
        bool failedQuietly = false;
        if (status == 0)
            status = exitCodeOf([&] {
                try {
                    body(ranks);
                } catch (const FatalError&) {
                    if (ranks.rank() == 0) throw;
                    failedQuietly = true;
                }
            });
        if (failedQuietly) status = 1;
    }
    MPI_Finalize();
    return status;
}

}  // namespace sph::parallel
