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
#include <cstdint>
#include <span>

namespace sph {

class ExactSum {
public:
    static constexpr int binCount = 67;  // 2098 bit places of doubles' terms, plus room for carries

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

}  // namespace sph
