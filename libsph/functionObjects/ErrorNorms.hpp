// Error norms over a set of samples (particles, probe times), each divided by a stated scale:
//   L1 = mean |e| / scale,  L2 = sqrt(mean e^2) / scale,  Linf = max |e| / scale.
#pragma once

#include <algorithm>
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

class ErrorAccumulator {
public:
    void add(double error) {
        const double magnitude = std::abs(error);
        sum_ += magnitude;
        sumOfSquares_ += magnitude * magnitude;
        max_ = std::max(max_, magnitude);
        ++count_;
    }
    void merge(const ErrorAccumulator& other) {
        sum_ += other.sum_;
        sumOfSquares_ += other.sumOfSquares_;
        max_ = std::max(max_, other.max_);
        count_ += other.count_;
    }
    std::size_t count() const { return count_; }
    // NaN norms when nothing was compared.
    ErrorNorms norms(double scale) const {
        if (count_ == 0) return {};
        const double n = static_cast<double>(count_);
        return {sum_ / n / scale, std::sqrt(sumOfSquares_ / n) / scale, max_ / scale};
    }

private:
    double sum_ = 0.0, sumOfSquares_ = 0.0, max_ = 0.0;
    std::size_t count_ = 0;
};

// What a function object reports to the run's closing error summary.
struct ReportedError {
    std::string quantity;  // "U", "p at P1", "front", ...
    ErrorNorms norms;
    std::string normalisation;  // what the norms are divided by, in words ("scale 0.05715")
};

}  // namespace sph
