#include "parallel/ReductionsOverRanks.hpp"

#include <algorithm>
#include <vector>

namespace sph::parallel {

// Each rank's bins, normalised, add as integers (each below 2^32, so that no sum over up to 2^31
// ranks overflows); the non-finite parts (0, infinities or NaN) add as doubles, alike in any order.
void ReductionsOverRanks::sum(std::span<ExactSum> sums) const {
    std::vector<std::int64_t> bins;
    std::vector<double> nonFinite;
    bins.reserve(sums.size() * ExactSum::binCount);
    for (ExactSum& s : sums) {
        s.normalise();
        bins.insert(bins.end(), s.bins().begin(), s.bins().end());
        nonFinite.push_back(s.nonFinite());
    }
    ranks_.sumOverRanks(bins);
    const std::vector<double> everyRanks = ranks_.gatherToAll(nonFinite);
    for (std::size_t k = 0; k < sums.size(); ++k) {
        const auto first = bins.begin() + static_cast<std::ptrdiff_t>(k * ExactSum::binCount);
        std::copy(first, first + ExactSum::binCount, sums[k].bins().begin());
        sums[k].nonFinite() = 0.0;
        for (std::size_t at = k; at < everyRanks.size(); at += sums.size()) sums[k].nonFinite() += everyRanks[at];
    }
}

}  // namespace sph::parallel
