#include "core/ExactSum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

double sumOf(const std::vector<double>& terms) {
    sph::ExactSum sum;
    for (const double term : terms) sum.add(term);
    return sum.value();
}

}  // namespace

TEST(ExactSum, KeepsWhatAPlainSumLoses) {
    EXPECT_EQ(sumOf({1e16, 1.0, -1e16}), 1.0);  // a plain sum gives 0
    EXPECT_EQ(sumOf({1.0, 1e-300, -1.0}), 1e-300);
    EXPECT_EQ(sumOf({0.1, 0.2, -0.3}), std::ldexp(1.0, -55));  // what the doubles 0.1, 0.2 and 0.3 leave; a plain sum gives 2^-54
    EXPECT_EQ(sumOf({std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::denorm_min()}),
              2.0 * std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(sumOf({std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), -2.5}), -2.5);
    EXPECT_EQ(sumOf({}), 0.0);
}

TEST(ExactSum, AgreesWithAnIntegerSumOfIntegers) {
    std::mt19937_64 random(3);
    std::uniform_int_distribution<std::int64_t> integer(-(std::int64_t{1} << 52), std::int64_t{1} << 52);
    std::vector<double> terms;
    std::int64_t exact = 0;
    for (int k = 0; k < 1000; ++k) {
        const std::int64_t n = integer(random);
        exact += n;
        terms.push_back(static_cast<double>(n));
    }
    EXPECT_EQ(sumOf(terms), static_cast<double>(exact));
}

TEST(ExactSum, DoesNotDependOnTheOrderOrTheSplitIntoPartialSums) {
    std::mt19937_64 random(5);
    std::normal_distribution<double> mantissa(0.0, 1.0);
    std::uniform_int_distribution<int> exponent(-40, 40);
    std::vector<double> terms;
    for (int k = 0; k < 20000; ++k) terms.push_back(std::ldexp(mantissa(random), exponent(random)));
    for (int k = 0; k < 2000; ++k) terms.push_back(-terms[static_cast<std::size_t>(k) * 7]);  // cancellation
    const double reference = sumOf(terms);
    bool plainSumsDiffer = false;
    for (int shuffle = 0; shuffle < 5; ++shuffle) {
        std::shuffle(terms.begin(), terms.end(), random);
        EXPECT_EQ(sumOf(terms), reference);
        double plain = 0.0;
        for (const double term : terms) plain += term;
        plainSumsDiffer = plainSumsDiffer || plain != reference;
        // Three "ranks" each summing a part, then their sums added.
        std::vector<sph::ExactSum> parts(3);
        for (std::size_t k = 0; k < terms.size(); ++k) parts[k * 3 / terms.size()].add(terms[k]);
        parts[2].add(parts[0]);
        parts[2].add(parts[1]);
        EXPECT_EQ(parts[2].value(), reference);
    }
    EXPECT_TRUE(plainSumsDiffer);  // the terms are such that the order would show
    // Within an ulp of the sum in long double of the same terms, sorted by magnitude.
    std::sort(terms.begin(), terms.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    long double careful = 0.0L;
    for (const double term : terms) careful += term;
    EXPECT_LE(std::abs(reference - static_cast<double>(careful)), std::abs(reference) * std::numeric_limits<double>::epsilon());
}

TEST(ExactSum, NonFiniteTermsSumAsIeeeAddsThem) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(sumOf({1.0, inf, 2.0}), inf);
    EXPECT_EQ(sumOf({-inf, 1.0}), -inf);
    EXPECT_TRUE(std::isnan(sumOf({inf, 1.0, -inf})));
    EXPECT_TRUE(std::isnan(sumOf({std::nan(""), 1.0})));
}

TEST(ExactSum, BinsSummedAsIntegersGiveTheWholeSum) {
    // What a reduction over processes does: each normalises, the bins add as integers.
    std::vector<sph::ExactSum> parts(4);
    std::vector<double> all;
    for (int k = 0; k < 400; ++k) {
        const double term = std::ldexp(1.0 + 0.001 * k, (k % 9) * 50 - 200) * (k % 3 == 0 ? -1.0 : 1.0);
        parts[static_cast<std::size_t>(k % 4)].add(term);
        all.push_back(term);
    }
    sph::ExactSum reduced;
    for (sph::ExactSum& part : parts) {
        part.normalise();
        for (std::size_t b = 0; b < sph::ExactSum::binCount; ++b) reduced.bins()[b] += part.bins()[b];
        reduced.nonFinite() += part.nonFinite();
    }
    EXPECT_EQ(reduced.value(), sumOf(all));
}
