// Halo copies: each rank receives, after its owned particles, copies of the particles other ranks
// own within `width` of its box (across periodic seams too, unshifted: the pair arithmetic takes
// the nearest image as in a serial run). The lists are built once per migration; between two,
// `refresh` sends the owners' new values of the arrays a stage needs. Messages go to the ranks
// whose boxes lie within `width` only, never to all.
#pragma once

#include "core/ParticleSet.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DomainBoxes.hpp"
#include "core/FieldBytes.hpp"

#include <cstdint>
#include <vector>

namespace sph::parallel {

template <int D>
class HaloExchange {
public:
    // Collective. Drops the set's halos, lists what goes where, and fills the new halos with
    // every array (global ids, positions, every field).
    HaloExchange(const Communicator& ranks, ParticleSet<D>& set, const DomainBoxes<D>& boxes, double width);

    // Collective. The owners' current values of `fields` to their copies, e.g.
    // halos.refresh(fluid, fields::velocity, fields::density).
    template <class... Keys>
    void refresh(ParticleSet<D>& set, Keys... keys) const {
        exchange({bytesOf(set[keys])...});
    }
    // The positions and `fields`, in one message per neighbour.
    template <class... Keys>
    void refreshPositions(ParticleSet<D>& set, Keys... keys) const {
        exchange({bytesOf(set.position), bytesOf(set[keys])...});
    }

    // After set.keep(order) on the set the exchange filled (owned particles and copies mixed, in
    // another order): the lists follow the particles to their new places.
    void reorder(const std::vector<std::uint32_t>& order);

    // The ranks this one exchanges with, ascending.
    const std::vector<int>& neighbours() const { return neighbours_; }
    std::size_t sentCount() const;
    // What this rank's exchanges sent so far (the first fill included): bytes and messages.
    std::size_t bytesSent() const { return bytesSent_; }
    std::size_t messagesSent() const { return messagesSent_; }

private:
    void exchange(const std::vector<FieldBytes>& arrays) const;

    Communicator ranks_;
    std::vector<int> neighbours_;
    std::vector<std::vector<std::uint32_t>> sendLists_;      // per neighbour: owned particles
    std::vector<std::vector<std::uint32_t>> receivePlaces_;  // per neighbour: where its copies go
    mutable std::size_t bytesSent_ = 0, messagesSent_ = 0;
};

}  // namespace sph::parallel
