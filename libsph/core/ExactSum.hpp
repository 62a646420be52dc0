// A sum of doubles kept exactly, so that its value does not depend on the order of the terms:
// a decomposed run's function objects add each rank's particles, then the ranks' sums, and
// report what the serial run reports to the last bit (a total momentum of a symmetric flow is
// mostly cancellation, where a plain sum's order shows in the ninth digit).
//
// Each finite term m 2^e (m an integer below 2^53, e from -1074) is cut into 32-bit digits
// added to 64-bit bins, bin k weighing 2^(32 k - 1074); a bin absorbs 2^31 terms before its
// carries must move up, which add() does every 2^30 terms. value() rounds the exact sum to a
// double (the digits from the top, to within an ulp: a function of the sum alone). Infinities
// and NaN are summed apart, as IEEE adds them (in any order alike).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <span>

namespace sph {

class ExactSum {
public:
    static constexpr int binCount = 67;   // 2098 bit places of doubles' terms, plus room for carries
    static constexpr int digitBits = 32;  // a bin's digit, when normalised
    static constexpr std::int64_t digitBase = std::int64_t{1} << digitBits;

    void add(double term);
    void add(const ExactSum& other);
    double value() const;

    // The state, for a reduction over processes: bins add as integers, the non-finite part as
    // doubles. normalise() first, so that a sum of up to 2^31 states cannot overflow a bin.
    void normalise();
    std::span<std::int64_t, binCount> bins() { return bins_; }
    double& nonFinite() { return nonFinite_; }

private:
    std::array<std::int64_t, binCount> bins_{};
    double nonFinite_ = 0.0;
    std::int64_t termsSinceNormalised_ = 0;
};

// Inline: a sum over every particle each step calls it millions of times.
inline void ExactSum::add(double term) {
    // The term's fields, read from its bits (frexp and ldexp would take most of the time).
    const auto bits = std::bit_cast<std::uint64_t>(term);
    const auto biasedExponent = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
    if (biasedExponent == 0x7ff) {
        nonFinite_ += term;
        return;
    }
    if (biasedExponent == 0 && mantissa == 0) return;
    // term = mantissa 2^(place - 1074): a normal number's mantissa has its leading bit, a
    // subnormal's (biased exponent 0) place is 0.
    int place = 0;
    if (biasedExponent > 0) {
        mantissa |= std::uint64_t{1} << 52;
        place = biasedExponent - 1;
    }
    // The mantissa shifted to its place within the bin, as three 32-bit digits.
    const int shift = place % digitBits;
    const std::uint64_t mask = digitBase - 1;
    const std::uint64_t low = (mantissa & mask) << shift;
    const std::uint64_t high = ((mantissa >> digitBits) << shift) + (low >> digitBits);
    const std::array<std::uint64_t, 3> digits{low & mask, high & mask, high >> digitBits};
    const std::size_t bin = static_cast<std::size_t>(place / digitBits);
    const std::int64_t sign = (bits >> 63) != 0 ? -1 : 1;
    for (std::size_t k = 0; k < digits.size(); ++k) bins_[bin + k] += sign * static_cast<std::int64_t>(digits[k]);
    if (++termsSinceNormalised_ == std::int64_t{1} << 30) normalise();
}

}  // namespace sph
