// The ranks of one run, and the decisions they take together. Every member is collective: all
// ranks call it, in the same order, or the run hangs. A rank never takes a path alone; it
// reports what it found (a failure, a wish to stop) and the ranks act on the agreed answer.
#pragma once

#include "core/FatalError.hpp"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sph::parallel {

// A FatalError that every rank threw together (Communicator::stopIfAnyFailed), with the failing
// rank's message: passed on as it is by an enclosing `together`.
class RanksStopped : public FatalError {
public:
    using FatalError::FatalError;
};

// A message's length as MPI counts it (int); a message past 2 GiB would need a derived type,
// which no exchange here comes near (a 3D particle with every field is under 300 bytes).
int mpiByteCount(std::size_t bytes);

class Communicator {
public:
    explicit Communicator(MPI_Comm ranks = MPI_COMM_WORLD);

    MPI_Comm handle() const { return ranks_; }
    int rank() const { return rank_; }
    int size() const { return size_; }

    double maxOverRanks(double value) const;
    std::int64_t sumOverRanks(std::int64_t value) const;
    // Each entry its largest value over the ranks, in place: several decisions in one message.
    void maxOverRanks(std::span<double> values) const;
    // Each entry its sum over the ranks, in place.
    void sumOverRanks(std::span<std::int64_t> values) const;
    // Rank 0's values on every rank.
    void broadcastFromFirst(std::span<double> values) const;
    std::string broadcastFromFirst(std::string text) const;

    // Throws RanksStopped on every rank when any rank passes an error: the message is that of
    // the lowest failing rank, prefixed with its number. Returns on every rank otherwise.
    void stopIfAnyFailed(const std::optional<std::string>& error) const;

    // Every rank sends toRank[r] to rank r and receives from each rank what it sent here:
    // the bytes from rank 0 first, then rank 1's, ...; fromRank[r] says how many came from r.
    std::vector<std::byte> exchangeWithAll(const std::vector<std::vector<std::byte>>& toRank, std::vector<std::size_t>& fromRank) const;

    // Waits for the requests: patiently where the ranks outnumber the cores (PatientWait.hpp).
    void wait(std::span<MPI_Request> requests) const;
    // Every rank receives every rank's values, rank 0's first.
    std::vector<double> gatherToAll(std::span<const double> mine) const;

    // Rank 0 receives every rank's bytes, rank 0's first (fromRank[r]: how many came from r);
    // the others receive nothing.
    std::vector<std::byte> gatherToFirst(const std::vector<std::byte>& mine, std::vector<std::size_t>& fromRank) const;

private:
    // Starts a nonblocking MPI call, whose last argument is its request, and waits for it:
    // complete(MPI_Ibcast, values, count, MPI_DOUBLE, 0, ranks_).
    template <class Start, class... Arguments>
    void complete(Start start, Arguments... arguments) const {
        MPI_Request request;
        start(arguments..., &request);
        wait(std::span<MPI_Request>(&request, 1));
    }

    MPI_Comm ranks_;
    int rank_ = 0;
    int size_ = 1;
    bool patient_ = false;
};

// Runs `body` on this rank; a FatalError it throws on any rank stops every rank with the first
// failing rank's message (stopIfAnyFailed).
template <class Body>
void together(const Communicator& ranks, Body&& body) {
    std::optional<std::string> error;
    try {
        body();
    } catch (const RanksStopped&) {
        throw;  // thrown on every rank, already with the failing rank's number
    } catch (const FatalError& e) {
        error = e.what();
    }
    ranks.stopIfAnyFailed(error);
}

}  // namespace sph::parallel
