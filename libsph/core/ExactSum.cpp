#include "core/ExactSum.hpp"

#include <cmath>

namespace sph {

namespace {

constexpr int digitBits = ExactSum::digitBits;
constexpr std::int64_t digitBase = ExactSum::digitBase;
constexpr int lowestExponent = -1074;  // of a subnormal's last bit

// Moves every bin's carry into the next, so that all but the top bin lie in [0, 2^32).
void carry(std::array<std::int64_t, ExactSum::binCount>& bins) {
    for (std::size_t k = 0; k + 1 < bins.size(); ++k) {
        const std::int64_t up = bins[k] >> digitBits;  // floor division: the remainder is the digit
        bins[k] -= up * digitBase;
        bins[k + 1] += up;
    }
}

}  // namespace

void ExactSum::add(const ExactSum& other) {
    ExactSum normalisedOther = other;
    normalisedOther.normalise();
    normalise();
    for (std::size_t k = 0; k < bins_.size(); ++k) bins_[k] += normalisedOther.bins_[k];
    nonFinite_ += other.nonFinite_;
}

void ExactSum::normalise() {
    carry(bins_);
    termsSinceNormalised_ = 0;
}

double ExactSum::value() const {
    if (nonFinite_ != 0.0) return nonFinite_;  // NaN too
    std::array<std::int64_t, binCount> digits = bins_;
    carry(digits);
    // The sign is the top bin's; a negative sum is rounded as its magnitude, whose digits are
    // then all of one sign.
    const bool negative = digits.back() < 0;
    if (negative) {
        for (std::int64_t& digit : digits) digit = -digit;
        carry(digits);
    }
    double magnitude = 0.0;
    for (std::size_t k = digits.size(); k-- > 0;)
        magnitude += std::ldexp(static_cast<double>(digits[k]), digitBits * static_cast<int>(k) + lowestExponent);
    return negative ? -magnitude : magnitude;
}

}  // namespace sph
