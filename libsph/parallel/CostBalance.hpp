// When a decomposed run repartitions, and how: the boxes of equal particle weight that the run
// starts with need not take equal time (particles beside walls, with more neighbours or with
// halo copies cost more), and the flow moves the work. Each rank measures the seconds of its own
// work (the stages of the evaluation, not the waits for the others) since the last partition.
// At a cell sort, once stepsPerCheck steps have passed since then, the slowest rank's seconds
// past `threshold` times the mean ask for new boxes, each rank weighing its particles by its
// measured seconds per particle, so that the next boxes even out the time.
//
//   mpirun -np 4 wcsph -parallel -balance 1.1     (the default; -balance 0: never repartition)
#pragma once

#include "parallel/Communicator.hpp"

#include <optional>

namespace sph::parallel {

class CostBalance {
public:
    static constexpr long stepsPerCheck = 100;
    static constexpr double defaultThreshold = 1.1;

    // threshold: the largest slowest-over-mean ratio left alone; 0 never repartitions.
    explicit CostBalance(double threshold, long startStep) : threshold_(threshold), lastStep_(startStep) {}

    struct Repartition {
        double weightPerParticle;  // for DistributedSystem::repartition
        double imbalance;          // the slowest rank's seconds over the mean, measured
    };

    // Collective: every rank takes the same decision. workSeconds: this rank's work since the
    // run began; ownedWeight: what its owned particles weigh in the partition now.
    std::optional<Repartition> check(const Communicator& ranks, long step, double workSeconds, double ownedWeight);

private:
    double threshold_;
    long lastStep_;
    double workAtLast_ = 0.0;
};

}  // namespace sph::parallel
