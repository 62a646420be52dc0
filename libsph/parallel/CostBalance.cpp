#include "parallel/CostBalance.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace sph::parallel {

std::optional<CostBalance::Repartition> CostBalance::check(const Communicator& ranks, long step, double workSeconds, double ownedWeight) {
    if (threshold_ <= 0.0 || step - lastStep_ < stepsPerCheck) return std::nullopt;
    // Every rank's two numbers on every rank (each fills its own slots of a max-reduction), so
    // that all sum them in the same order and decide alike.
    const auto size = static_cast<std::size_t>(ranks.size()), rank = static_cast<std::size_t>(ranks.rank());
    std::vector<double> all(2 * size, std::numeric_limits<double>::lowest());
    const double work = workSeconds - workAtLast_;
    all[2 * rank] = work;
    all[2 * rank + 1] = ownedWeight;
    ranks.maxOverRanks(all);
    double totalWork = 0.0, totalWeight = 0.0, slowest = 0.0;
    for (std::size_t r = 0; r < size; ++r) {
        totalWork += all[2 * r];
        totalWeight += all[2 * r + 1];
        slowest = std::max(slowest, all[2 * r]);
    }
    lastStep_ = step;
    workAtLast_ = workSeconds;
    const double imbalance = totalWork > 0.0 ? slowest * static_cast<double>(size) / totalWork : 1.0;
    if (imbalance <= threshold_) return std::nullopt;
    // Seconds per unit of weight, against the mean over all ranks: 1 on an average rank (and on
    // one that owns nothing: it weighs nothing either way).
    const double mean = totalWork / totalWeight;
    return Repartition{ownedWeight > 0.0 && work > 0.0 ? (work / ownedWeight) / mean : 1.0, imbalance};
}

}  // namespace sph::parallel
