// The domain around a block of particles [0, side)^D: a margin on every side, or with
// periodicX the block's x extent as a period (pairs across it count).
#pragma once

#include "core/Vector.hpp"

#include <array>

namespace sph::test {

template <int D>
struct BlockDomain {
    Vec<D> min = Vec<D>::Constant(-0.1), max;
    std::array<bool, D> periodic{};
};

template <int D>
BlockDomain<D> blockDomain(double side, bool periodicX) {
    BlockDomain<D> domain;
    domain.max = Vec<D>::Constant(side + 0.1);
    if (periodicX) {
        domain.min[0] = 0.0;
        domain.max[0] = side;
        domain.periodic[0] = true;
    }
    return domain;
}

}  // namespace sph::test
