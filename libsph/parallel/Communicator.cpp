#include "parallel/Communicator.hpp"

#include "core/FatalError.hpp"
#include "parallel/PatientWait.hpp"

#include <limits>
#include <stdexcept>

namespace sph::parallel {

int mpiByteCount(std::size_t bytes) {
    if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::length_error("an MPI message of " + std::to_string(bytes) + " bytes exceeds 2 GiB");
    return static_cast<int>(bytes);
}

Communicator::Communicator(MPI_Comm ranks) : ranks_(ranks) {
    MPI_Comm_rank(ranks_, &rank_);
    MPI_Comm_size(ranks_, &size_);
    patient_ = ranksOutnumberCores();
}

void Communicator::wait(std::span<MPI_Request> requests) const {
    if (patient_)
        waitPatiently(requests);
    else
        MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

double Communicator::maxOverRanks(double value) const {
    double result = value;
    complete(MPI_Iallreduce, &value, &result, 1, MPI_DOUBLE, MPI_MAX, ranks_);
    return result;
}

std::int64_t Communicator::sumOverRanks(std::int64_t value) const {
    std::int64_t result = value;
    complete(MPI_Iallreduce, &value, &result, 1, MPI_INT64_T, MPI_SUM, ranks_);
    return result;
}

void Communicator::maxOverRanks(std::span<double> values) const {
    complete(MPI_Iallreduce, MPI_IN_PLACE, values.data(), mpiByteCount(values.size()), MPI_DOUBLE, MPI_MAX, ranks_);
}

void Communicator::sumOverRanks(std::span<std::int64_t> values) const {
    complete(MPI_Iallreduce, MPI_IN_PLACE, values.data(), mpiByteCount(values.size()), MPI_INT64_T, MPI_SUM, ranks_);
}

void Communicator::broadcastFromFirst(std::span<double> values) const {
    complete(MPI_Ibcast, values.data(), mpiByteCount(values.size()), MPI_DOUBLE, 0, ranks_);
}

std::string Communicator::broadcastFromFirst(std::string text) const {
    int length = mpiByteCount(text.size());
    complete(MPI_Ibcast, &length, 1, MPI_INT, 0, ranks_);
    text.resize(static_cast<std::size_t>(length));
    complete(MPI_Ibcast, text.data(), length, MPI_CHAR, 0, ranks_);
    return text;
}

void Communicator::stopIfAnyFailed(const std::optional<std::string>& error) const {
    const int mine = error ? rank_ : size_;
    int firstFailing = size_;
    complete(MPI_Iallreduce, &mine, &firstFailing, 1, MPI_INT, MPI_MIN, ranks_);
    if (firstFailing == size_) return;
    std::string message = rank_ == firstFailing ? *error : std::string();
    int length = mpiByteCount(message.size());
    complete(MPI_Ibcast, &length, 1, MPI_INT, firstFailing, ranks_);
    message.resize(static_cast<std::size_t>(length));
    complete(MPI_Ibcast, message.data(), length, MPI_CHAR, firstFailing, ranks_);
    throw RanksStopped("rank " + std::to_string(firstFailing) + " of " + std::to_string(size_) + ": " + message);
}

std::vector<std::byte> Communicator::gatherToFirst(const std::vector<std::byte>& mine, std::vector<std::size_t>& fromRank) const {
    const int count = mpiByteCount(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    complete(MPI_Igather, &count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, ranks_);
    std::size_t total = 0;
    fromRank.assign(counts.begin(), counts.end());
    for (std::size_t r = 0; r < counts.size() && rank_ == 0; ++r) offsets[r] = mpiByteCount(total), total += fromRank[r];
    std::vector<std::byte> gathered(total);
    complete(MPI_Igatherv, mine.data(), count, MPI_BYTE, gathered.data(), counts.data(), offsets.data(), MPI_BYTE, 0, ranks_);
    return gathered;
}

std::vector<double> Communicator::gatherToAll(std::span<const double> mine) const {
    const int count = mpiByteCount(mine.size_bytes()) / static_cast<int>(sizeof(double));
    std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    complete(MPI_Iallgather, &count, 1, MPI_INT, counts.data(), 1, MPI_INT, ranks_);
    int total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) offsets[r] = total, total += counts[r];
    std::vector<double> gathered(static_cast<std::size_t>(total));
    complete(MPI_Iallgatherv, mine.data(), count, MPI_DOUBLE, gathered.data(), counts.data(), offsets.data(), MPI_DOUBLE, ranks_);
    return gathered;
}

std::vector<std::byte> Communicator::exchangeWithAll(const std::vector<std::vector<std::byte>>& toRank, std::vector<std::size_t>& fromRank) const {
    const auto ranks = static_cast<std::size_t>(size_);
    if (toRank.size() != ranks) throw std::logic_error("exchangeWithAll needs one buffer per rank");
    std::vector<int> sendCounts(ranks), receiveCounts(ranks), sendOffsets(ranks), receiveOffsets(ranks);
    std::vector<std::byte> sent;
    for (std::size_t r = 0; r < ranks; ++r) {
        sendCounts[r] = mpiByteCount(toRank[r].size());
        sendOffsets[r] = mpiByteCount(sent.size());
        sent.insert(sent.end(), toRank[r].begin(), toRank[r].end());
    }
    complete(MPI_Ialltoall, sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, ranks_);
    std::size_t total = 0;
    fromRank.assign(ranks, 0);
    for (std::size_t r = 0; r < ranks; ++r) {
        receiveOffsets[r] = mpiByteCount(total);
        fromRank[r] = static_cast<std::size_t>(receiveCounts[r]);
        total += fromRank[r];
    }
    std::vector<std::byte> received(total);
    complete(MPI_Ialltoallv, sent.data(), sendCounts.data(), sendOffsets.data(), MPI_BYTE, received.data(), receiveCounts.data(),
             receiveOffsets.data(), MPI_BYTE, ranks_);
    return received;
}

}  // namespace sph::parallel
