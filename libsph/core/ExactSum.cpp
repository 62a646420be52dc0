#include "core/ExactSum.hpp"

#include <cmath>

namespace sph {

namespace {

constexpr int digitBits = 32;
constexpr int lowestExponent = -1074;  // of a subnormal's last bit
constexpr std::int64_t digitBase = std::int64_t{1} << digitBits;

// Moves every bin's carry into the next, so that all but the top bin lie in [0, 2^32).
void carry(std::array<std::int64_t, ExactSum::binCount>& bins) {
    for (std::size_t k = 0; k + 1 < bins.size(); ++k) {
        const std::int64_t up = bins[k] >> digitBits;  // floor division: the remainder is the digit
        bins[k] -= up * digitBase;
        bins[k + 1] += up;
    }
}

}  // namespace

void ExactSum::add(double term) {
    if (!std::isfinite(term)) {
        nonFinite_ += term;
        return;
    }
    if (term == 0.0) return;
    int exponent = 0;
    const double fraction = std::frexp(std::abs(term), &exponent);  // term = fraction 2^exponent, fraction in [0.5, 1)
    // The 53-bit integer mantissa and the place of its last bit above 2^-1074 (a subnormal's
    // mantissa has fewer bits, and its place is 0).
    int place = exponent - 53 - lowestExponent;
    auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
    if (place < 0) {
        mantissa >>= -place;  // exact: a subnormal's bits below 2^-1074 are zero
        place = 0;
    }
    // The mantissa shifted to its place within the bin, as three 32-bit digits.
    const int shift = place % digitBits;
    const std::uint64_t mask = digitBase - 1;
    const std::uint64_t low = (mantissa & mask) << shift;
    const std::uint64_t high = ((mantissa >> digitBits) << shift) + (low >> digitBits);
    const std::array<std::uint64_t, 3> digits{low & mask, high & mask, high >> digitBits};
    const std::size_t bin = static_cast<std::size_t>(place / digitBits);
    const std::int64_t sign = term < 0.0 ? -1 : 1;
    for (std::size_t k = 0; k < digits.size(); ++k) bins_[bin + k] += sign * static_cast<std::int64_t>(digits[k]);
    if (++termsSinceNormalised_ == std::int64_t{1} << 30) normalise();
}

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
