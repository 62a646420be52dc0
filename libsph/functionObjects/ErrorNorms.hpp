// Error norms over a set of samples (particles, probe times), each divided by a stated scale:
//   L1 = mean |e| / scale,  L2 = sqrt(mean e^2) / scale,  Linf = max |e| / scale.
#pragma once

#include "core/ExactSum.hpp"
#include "functionObjects/Reductions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace sph {

struct ErrorNorms {
    double l1 = std::numeric_limits<double>::quiet_NaN();
    double l2 = std::numeric_limits<double>::quiet_NaN();
    double linf = std::numeric_limits<double>::quiet_NaN();
};

// The sums are exact (core/ExactSum): the norms do not depend on the samples' order, nor on how
// processes that each hold a share of them (a decomposed run) split them.
class ErrorAccumulator {
public:
    void add(double error) {
        const double magnitude = std::abs(error);
        sums_[0].add(magnitude);
        sums_[1].add(magnitude * magnitude);
        sums_[2].add(1.0);
        max_ = std::max(max_, magnitude);
    }
    void merge(const ErrorAccumulator& other) {
        for (std::size_t k = 0; k < sums_.size(); ++k) sums_[k].add(other.sums_[k]);
        max_ = std::max(max_, other.max_);
    }
    // Collective: every process's samples, on every process.
    void combine(const Reductions& reductions) {
        reductions.sum(sums_);
        max_ = reductions.max(max_);
    }
    std::size_t count() const { return static_cast<std::size_t>(sums_[2].value()); }
    // NaN norms when nothing was compared.
    ErrorNorms norms(double scale) const {
        const double n = sums_[2].value();
        if (n == 0.0) return {};
        return {sums_[0].value() / n / scale, std::sqrt(sums_[1].value() / n) / scale, max_ / scale};
    }

private:
    std::array<ExactSum, 3> sums_;  // |e|, e^2, and the count
    double max_ = 0.0;
};

// What a function object reports to the run's closing error summary.
struct ReportedError {
    std::string quantity;  // "U", "p at P1", "front", ...
    ErrorNorms norms;
    std::string normalisation;  // what the norms are divided by, in words ("scale 0.05715")
};

}  // namespace sph
