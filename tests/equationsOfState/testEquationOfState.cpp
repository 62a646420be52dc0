#include "equationsOfState/EquationOfState.hpp"

#include <gtest/gtest.h>

using sph::LinearEquationOfState;
using sph::TaitEquationOfState;

TEST(TaitEquationOfState, StiffnessFromSpeedOfSound) {
    const TaitEquationOfState eos(1000.0, 20.0, 7.0, 0.0);
    EXPECT_DOUBLE_EQ(eos.B, 20.0 * 20.0 * 1000.0 / 7.0);
    // dp/drho at rho0 is c0^2.
    const double e = 1e-4;
    EXPECT_NEAR((eos.pressure(1000.0 + e) - eos.pressure(1000.0 - e)) / (2 * e), 400.0, 1e-6);
}

TEST(TaitEquationOfState, HandComputedPressure) {
    const TaitEquationOfState eos(1000.0, 10.0, 7.0, 50.0);
    // B = 100 * 1000 / 7; (1.01^7 - 1) = 0.0721353...
    EXPECT_NEAR(eos.pressure(1010.0), 100000.0 / 7.0 * (std::pow(1.01, 7) - 1.0) + 50.0, 1e-9);
    EXPECT_DOUBLE_EQ(eos.pressure(1000.0), 50.0);
}

TEST(TaitEquationOfState, WholeGammaBySquaringEqualsPow) {
    // gamma 7 takes the repeated-squaring path, 7.5 std::pow; both against std::pow here.
    for (double gamma : {7.0, 1.0, 7.5}) {
        const TaitEquationOfState eos(1000.0, 30.0, gamma, 0.0);
        for (double rho : {900.0, 999.9, 1000.1, 1013.0, 1200.0})
            EXPECT_NEAR(eos.pressure(rho), eos.B * (std::pow(rho / 1000.0, gamma) - 1.0), 1e-14 * eos.B) << gamma << " " << rho;
    }
    EXPECT_EQ(TaitEquationOfState(1000.0, 30.0, 7.0, 0.0).wholeGamma, 7);
    EXPECT_EQ(TaitEquationOfState(1000.0, 30.0, 7.5, 0.0).wholeGamma, 0);
}

TEST(TaitEquationOfState, DensityInvertsPressure) {
    const TaitEquationOfState eos(998.0, 35.0, 7.0, 1e3);
    for (double rho : {950.0, 998.0, 1003.0, 1100.0}) EXPECT_NEAR(eos.density(eos.pressure(rho)), rho, 1e-9 * rho);
}

TEST(LinearEquationOfState, PressureAndInverse) {
    const LinearEquationOfState eos(1000.0, 10.0, 5.0);
    EXPECT_DOUBLE_EQ(eos.pressure(1001.0), 100.0 + 5.0);
    for (double rho : {990.0, 1000.0, 1020.0}) EXPECT_NEAR(eos.density(eos.pressure(rho)), rho, 1e-9 * rho);
    EXPECT_DOUBLE_EQ(eos.stiffness(), 1000.0 * 100.0);
}

TEST(EquationOfStateRegistry, ReadsCoefficientsFromTheDictionary) {
    const auto registry = sph::makeEquationOfStateRegistry();
    const auto dict = sph::Dictionary::fromString("gamma 1; backgroundPressure 10;", "eos");
    const auto eos = registry.create("tait", {}, dict, 1000.0, 30.0);
    const auto& tait = std::get<TaitEquationOfState>(eos);
    EXPECT_DOUBLE_EQ(tait.gamma, 1.0);
    EXPECT_DOUBLE_EQ(tait.p0, 10.0);
    EXPECT_DOUBLE_EQ(tait.B, 900.0 * 1000.0);
}
