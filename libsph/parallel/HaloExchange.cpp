#include "parallel/HaloExchange.hpp"

#include <numeric>
#include <span>

namespace sph::parallel {

template <int D>
HaloExchange<D>::HaloExchange(const Communicator& ranks, ParticleSet<D>& set, const DomainBoxes<D>& boxes, double width) : ranks_(ranks) {
    const std::size_t owned = set.ownedCount();
    set.resize(owned);
    for (int r = 0; r < ranks.size(); ++r)
        if (r != ranks.rank() && boxes.within(ranks.rank(), r, width)) neighbours_.push_back(r);
    sendLists_.resize(neighbours_.size());
    for (std::size_t k = 0; k < neighbours_.size(); ++k)
        for (std::size_t i = 0; i < owned; ++i)
            if (boxes.distanceToBox(set.position[i], neighbours_[k]) <= width) sendLists_[k].push_back(static_cast<std::uint32_t>(i));

    // Each neighbour says how many it sends, so that the halos can be sized before any arrive.
    std::vector<std::uint64_t> sending(neighbours_.size()), receiving(neighbours_.size());
    std::vector<MPI_Request> requests;
    requests.reserve(2 * neighbours_.size());
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        sending[k] = sendLists_[k].size();
        MPI_Irecv(&receiving[k], 1, MPI_UINT64_T, neighbours_[k], 0, ranks.handle(), &requests.emplace_back());
        MPI_Isend(&sending[k], 1, MPI_UINT64_T, neighbours_[k], 0, ranks.handle(), &requests.emplace_back());
    }
    ranks_.wait(requests);
    std::uint32_t next = static_cast<std::uint32_t>(owned);
    receivePlaces_.resize(neighbours_.size());
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        receivePlaces_[k].resize(receiving[k]);
        std::iota(receivePlaces_[k].begin(), receivePlaces_[k].end(), next);
        next += static_cast<std::uint32_t>(receiving[k]);
    }
    set.resizeHalos(next - owned);
    exchange(everyArray(set));
}

template <int D>
void HaloExchange<D>::reorder(const std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> placeOf(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) placeOf[order[i]] = static_cast<std::uint32_t>(i);
    for (auto* lists : {&sendLists_, &receivePlaces_})
        for (auto& list : *lists)
            for (std::uint32_t& place : list) place = placeOf[place];
}

template <int D>
std::size_t HaloExchange<D>::sentCount() const {
    std::size_t sent = 0;
    for (const auto& list : sendLists_) sent += list.size();
    return sent;
}

template <int D>
void HaloExchange<D>::exchange(const std::vector<FieldBytes>& arrays) const {
    const std::size_t record = bytesPerParticle(arrays);
    const std::size_t neighbours = neighbours_.size();
    std::vector<std::vector<std::byte>> outgoing(neighbours), incoming(neighbours);
    std::vector<MPI_Request> requests;
    requests.reserve(2 * neighbours);
    for (std::size_t k = 0; k < neighbours; ++k) {
        incoming[k].resize(receivePlaces_[k].size() * record);
        MPI_Irecv(incoming[k].data(), mpiByteCount(incoming[k].size()), MPI_BYTE, neighbours_[k], 1, ranks_.handle(), &requests.emplace_back());
    }
    for (std::size_t k = 0; k < neighbours; ++k) {
        pack(arrays, sendLists_[k], outgoing[k]);
        bytesSent_ += outgoing[k].size();
        ++messagesSent_;
        MPI_Isend(outgoing[k].data(), mpiByteCount(outgoing[k].size()), MPI_BYTE, neighbours_[k], 1, ranks_.handle(), &requests.emplace_back());
    }
    ranks_.wait(requests);
    for (std::size_t k = 0; k < neighbours; ++k) unpack(arrays, receivePlaces_[k], incoming[k]);
}

template class HaloExchange<1>;
template class HaloExchange<2>;
template class HaloExchange<3>;

}  // namespace sph::parallel
