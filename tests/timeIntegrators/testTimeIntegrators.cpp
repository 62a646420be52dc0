// Every registered integrator: convergence order on ODEs with a known solution (a falling
// particle; a linear oscillator that is no SPH system at all) and on a small SPH drop
// (self-convergence), energy over 100 periods, counters, adaptive error control, and the IMEX
// integrator's stability at a viscous step far above the explicit limit.
#include "io/SelectByType.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/IntegrableSystem.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <numbers>

using namespace sph;

namespace {

std::unique_ptr<TimeIntegrator<2>> makeIntegrator(const std::string& entries) {
    const Dictionary dict = Dictionary::fromString("integrator { " + entries + " }", "timeIntegration");
    const Dictionary& integrator = dict.subDict("integrator");
    auto result = selectByType(makeTimeIntegratorRegistry<2>(), integrator, integrator);
    integrator.checkUnused();
    return result;
}

// One particle alone: gravity is its only force.
std::unique_ptr<FluidSystem<2>> singleParticle(const Vec<2>& x, const Vec<2>& v, const Vec<2>& gravity, double rampTime) {
    ParticleSet<2> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = x;
    fluid.add(fields::velocity, v);
    fluid.add(fields::density, 1000.0);
    fluid.add(fields::mass, 1.0);
    ParticleSet<2> walls("walls");
    walls.add(fields::mass, 0.0);
    FluidModels<2> models{WendlandC2<2>(0.01), TaitEquationOfState(1000.0, 10.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    return std::make_unique<FluidSystem<2>>(std::move(models), std::move(fluid), std::move(walls), std::vector<Patch<2>>{}, Vec<2>(-2, -2),
                                            Vec<2>(4, 4), gravity, rampTime);
}

// One particle falling under the ramped gravity g (sin((t - 1/2) pi) + 1)/2 from rest:
// y(1) = -1/4 + 1/pi^2.
double fallError(const std::string& entries, int steps) {
    auto particle = singleParticle(Vec<2>::Zero(), Vec<2>::Zero(), Vec<2>(0.0, -1.0), 1.0);
    FluidSystem<2>& system = *particle;
    auto integrator = makeIntegrator(entries);
    system.evaluateRates(0.0);
    // An adaptive integrator may take more, shorter steps than asked.
    const double dt = 1.0 / steps;
    double t = 0.0;
    while (t < 1.0 - 1e-12) t += integrator->step(system, t, std::min(dt, 1.0 - t));
    const double exact = -0.25 + 1.0 / (std::numbers::pi * std::numbers::pi);
    return std::abs(system.fluid.position[0].y() - exact);
}

struct OrderCase {
    std::string entries;
    double order;
    int steps;  // coarse step count: error well above round-off at 2x the steps
};

// The test's name: the dictionary entries without their punctuation.
std::string caseName(const ::testing::TestParamInfo<OrderCase>& info) {
    std::string name;
    for (char c : info.param.entries)
        if (std::isalnum(static_cast<unsigned char>(c))) name += c;
    return name;
}

// Every integrator, with the order the known-solution tests expect of it.
const std::vector<OrderCase> knownSolutionOrders = {OrderCase{"type symplectic;", 2, 20},
                                                    OrderCase{"type verlet; eulerEvery 1000000;", 2, 20},
                                                    OrderCase{"type verlet; eulerEvery 1;", 1, 20},
                                                    OrderCase{"type leapfrog;", 2, 20},
                                                    OrderCase{"type predictorCorrector;", 2, 20},
                                                    OrderCase{"type arkodeERK; table ARKODE_HEUN_EULER_2_1_2;", 2, 20},
                                                    OrderCase{"type arkodeERK; table ARKODE_BOGACKI_SHAMPINE_4_2_3;", 3, 10},
                                                    OrderCase{"type arkodeERK; table ARKODE_ZONNEVELD_5_3_4;", 4, 8},
                                                    OrderCase{"type arkodeERK; table ARKODE_DORMAND_PRINCE_7_4_5;", 5, 8},
                                                    OrderCase{"type arkodeIMEX; table ARK324L2SA;", 3, 10}};

class IntegratorOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(IntegratorOrder, AtLeastTheNominalOrderOnAKnownSolution) {
    // With a force that depends on time only, a Runge-Kutta method reduces to its quadrature
    // rule, which may exceed the method's order (ARK324's explicit part reaches 4.4 here).
    const OrderCase& c = GetParam();
    const double observed = std::log2(fallError(c.entries, c.steps) / fallError(c.entries, 2 * c.steps));
    EXPECT_GT(observed, c.order - 0.25) << c.entries;
    EXPECT_LT(observed, c.order + 1.5) << c.entries;
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, IntegratorOrder, ::testing::ValuesIn(knownSolutionOrders), caseName);

TEST(IntegratorOrder, SecondOrderSchemesAreExactForConstantAccelerationWithVaryingSteps) {
    const Vec<2> x0(0.5, 2.0), v0(1.0, 3.0), g(0.0, -9.81);
    for (const std::string entries : {"type symplectic;", "type leapfrog;", "type predictorCorrector;"}) {
        auto system = singleParticle(x0, v0, g, 0.0);
        auto integrator = makeIntegrator(entries);
        system->evaluateRates(0.0);
        double t = 0.0;
        for (double dt : {0.01, 0.02, 0.005, 0.03}) t += integrator->step(*system, t, dt);
        const Vec<2> expected = x0 + v0 * t + 0.5 * g * t * t;
        EXPECT_NEAR((system->fluid.position[0] - expected).norm(), 0.0, 1e-13) << entries;
        EXPECT_NEAR((system->fluid[fields::velocity][0] - (v0 + g * t)).norm(), 0.0, 1e-13) << entries;
    }
}

// No SPH at all: a linear oscillator a = -x, one particle on the unit circle, advanced through
// IntegrableSystem alone. Its right-hand side depends on the state, so the observed order is
// the scheme's own, where a force of time alone only tests the scheme's quadrature.
class Oscillator final : public IntegrableSystem<2> {
public:
    Oscillator() : IntegrableSystem<2>(ParticleSet<2>("fluid"), ParticleSet<2>("walls")) {
        fluid.resize(1);
        fluid.position[0] = Vec<2>(1.0, 0.0);
        fluid.add(fields::velocity, Vec<2>(0.0, 1.0));
        fluid.add(fields::acceleration, Vec<2>::Zero());
    }
    void evaluateRates(double, RateTerms terms) override {
        fluid[fields::acceleration][0] = terms == RateTerms::ViscousOnly ? Vec<2>::Zero() : Vec<2>(-fluid.position[0]);
    }
    void predictBodies(double) override {}
    void correctBodies(double) override {}
    std::vector<std::string> freeBodyPatches() const override { return {}; }
    std::vector<std::string> patchesWithWallViscousStress() const override { return {}; }
    bool continuity() const override { return false; }
    bool wallDensityEvolves() const override { return false; }
    StateScales scales() const override { return {1.0, 1.0, 1.0}; }
    const Viscosity& viscosity() const override { return none_; }

    double energy() const { return 0.5 * (fluid.position[0].squaredNorm() + fluid[fields::velocity][0].squaredNorm()); }

private:
    Viscosity none_ = NoViscosity{};
};

// An explicit SUNDIALS table evaluates its stages but the first (the previous step's end), and
// the step's end only where no stage was there: a table whose last stage is the step's end
// (first same as last) hands over that stage's rates.
TEST(IntegratorCounters, ExplicitSundialsTablesEvaluateTheStepsEndOnlyWhereNoStageWasThere) {
    for (const auto& [entries, perStep] :
         std::vector<std::pair<std::string, long>>{{"type arkodeERK; table ARKODE_BOGACKI_SHAMPINE_4_2_3;", 3},  // 4 stages, the last at the end
                                                   {"type arkodeERK; table ARKODE_ZONNEVELD_5_3_4;", 5},         // 5, the last at 3/4 of the step
                                                   {"type arkodeERK; table ARKODE_HEUN_EULER_2_1_2;", 2}}) {     // 2, the last at y + h k1
        Oscillator system;
        auto integrator = makeIntegrator(entries);
        system.evaluateRates(0.0, RateTerms::All);
        double t = 0.0;
        for (int k = 0; k < 7; ++k) t += integrator->step(system, t, 0.01);
        EXPECT_EQ(integrator->counters()[1], (std::pair<std::string, long>{"right-hand-side evaluations", 7 * perStep})) << entries;
    }
}

// A restart after every step (what particle shifting asks for) starts from the step the
// integrator would take next, not from the last one the driver's stop time cut short: the
// adaptive steps keep their size.
TEST(AdaptiveIntegrators, RestartedEveryStepTheyKeepTheirStepSize) {
    const auto stepsToOne = [](bool restartEveryStep) {
        Oscillator system;
        auto integrator = makeIntegrator("type arkodeERK; adaptive yes; relativeTolerance 1e-6; absoluteTolerance 1e-8;");
        system.evaluateRates(0.0, RateTerms::All);
        double t = 0.0;
        int steps = 0;
        for (; t < 1.0 - 1e-12 && steps < 100000; ++steps) {
            t += integrator->step(system, t, std::min(0.05, 1.0 - t));
            if (restartEveryStep) integrator->stateChangedOutside();
        }
        return steps;
    };
    const int uninterrupted = stepsToOne(false);
    EXPECT_LE(stepsToOne(true), 2 * uninterrupted) << "uninterrupted: " << uninterrupted;
}

// The distance from the exact (cos t, sin t) at t = 1 after `steps` equal steps.
double oscillatorError(const std::string& entries, int steps) {
    Oscillator system;
    auto integrator = makeIntegrator(entries);
    system.evaluateRates(0.0, RateTerms::All);
    const double dt = 1.0 / steps;
    double t = 0.0;
    while (t < 1.0 - 1e-12) t += integrator->step(system, t, std::min(dt, 1.0 - t));
    return (system.fluid.position[0] - Vec<2>(std::cos(t), std::sin(t))).norm();
}

class OscillatorOrder : public ::testing::TestWithParam<OrderCase> {};

TEST_P(OscillatorOrder, TheNominalOrderWhereTheForceDependsOnTheState) {
    const OrderCase& c = GetParam();
    const double observed = std::log2(oscillatorError(c.entries, c.steps) / oscillatorError(c.entries, 2 * c.steps));
    EXPECT_NEAR(observed, c.order, 0.025) << c.entries;  // doc/models.md quotes each
}

INSTANTIATE_TEST_SUITE_P(AllIntegrators, OscillatorOrder, ::testing::ValuesIn(knownSolutionOrders), caseName);

constexpr int stepsPerPeriod = 20;

// The oscillator's energy, largest over each of `periods` periods of 20 steps each.
std::vector<double> oscillatorEnergyPeaks(const std::string& entries, int periods) {
    Oscillator system;
    auto integrator = makeIntegrator(entries);
    system.evaluateRates(0.0, RateTerms::All);
    const double dt = 2.0 * std::numbers::pi / stepsPerPeriod;
    std::vector<double> peaks(static_cast<std::size_t>(periods), 0.0);
    for (int k = 0; k < stepsPerPeriod * periods; ++k) {
        integrator->step(system, k * dt, dt);
        double& peak = peaks[static_cast<std::size_t>(k / stepsPerPeriod)];
        peak = std::max(peak, system.energy());
    }
    return peaks;
}

TEST(OscillatorEnergy, BoundedOverAHundredPeriodsWhereTheMapPreservesArea) {
    // Each of these schemes maps (x, v) by a matrix of determinant 1 on a linear oscillator:
    // the energy oscillates within the step's error (3e-4 here) and never drifts.
    for (const std::string entries : {"type symplectic;", "type leapfrog;", "type predictorCorrector;"}) {
        const auto peaks = oscillatorEnergyPeaks(entries, 100);
        EXPECT_NEAR(peaks.front(), 1.0, 3.2e-4) << entries;  // doc/models.md: within 3.1e-4
        // The peak is sampled at steps, whose phase within the period shifts: 2e-6 of scatter.
        EXPECT_NEAR(peaks.back(), peaks.front(), 1e-5) << entries;
    }
}

TEST(OscillatorEnergy, WhatVerletWithEulerStepsAndFixedStepBogackiShampineDoToIt) {
    // The figures doc/models.md quotes: Verlet's Euler step every 40 gains energy as well
    // (forward Euler's amplification exceeds 1), an explicit Runge-Kutta step loses it.
    EXPECT_NEAR(oscillatorEnergyPeaks("type verlet;", 100).back(), 43.4, 0.05);
    EXPECT_NEAR(1.0 - oscillatorEnergyPeaks("type arkodeERK;", 100).back(), 0.79, 0.005);
}

TEST(OscillatorEnergy, VerletGrowsAsItsAmplificationMatrixPredicts) {
    // Monaghan's Verlet maps (x^n, v^n, v^{n-1}) by [[a, w, 0], [-2w, 0, 1], [0, 1, 0]],
    // w = omega dt, a = 1 - w^2/2, whose characteristic polynomial is
    // l^3 - a l^2 - (1 - 2 w^2) l + a: one real root r in (-1, 0) (the polynomial is -2 w^2 at
    // -1 and a at 0) and a complex pair of modulus sqrt(-a / r), the product of the roots
    // being -a. That modulus exceeds 1 by O(w^4), so an undamped oscillation gains energy:
    // by 2.7 % per period at 20 steps per period. SPH runs rely on viscosity to damp it.
    const double w = 2.0 * std::numbers::pi / stepsPerPeriod, a = 1.0 - 0.5 * w * w;
    const auto characteristic = [&](double l) { return l * l * l - a * l * l - (1.0 - 2.0 * w * w) * l + a; };
    double realRoot = -1.0, above = 0.0;  // bisection
    for (int k = 0; k < 100; ++k) (characteristic(0.5 * (realRoot + above)) < 0.0 ? realRoot : above) = 0.5 * (realRoot + above);
    const double radius = std::sqrt(-a / realRoot);
    const auto peaks = oscillatorEnergyPeaks("type verlet; eulerEvery 1000000;", 100);
    // Between period 50 and 100 the decaying eigenvector is gone: the growth is the radius's.
    const double predicted = std::pow(radius, 2.0 * 50 * stepsPerPeriod);
    EXPECT_NEAR(peaks[99] / peaks[49], predicted, 0.01 * predicted);
    EXPECT_GT(predicted, 3.5);
}

TEST(AdaptiveIntegrators, ErrorFollowsTheTolerance) {
    // 1000 coarse steps allowed: the tolerance, not the step cap, sets the error.
    for (const std::string type : {"arkodeERK; adaptive yes;", "arkodeIMEX; adaptive yes;", "cvode;"}) {
        const double loose = fallError("type " + type + " relativeTolerance 1e-3; absoluteTolerance 1e-3;", 1);
        const double tight = fallError("type " + type + " relativeTolerance 1e-7; absoluteTolerance 1e-7;", 1);
        EXPECT_LT(tight, 1e-5) << type;
        EXPECT_LT(tight, 1e-2 * loose) << type;
        // The same where the force depends on the state (the Newton iterations of CVODE and the
        // stages of ERK each evaluate at a new state).
        const double looseOscillator = oscillatorError("type " + type + " relativeTolerance 1e-3; absoluteTolerance 1e-3;", 1);
        const double tightOscillator = oscillatorError("type " + type + " relativeTolerance 1e-7; absoluteTolerance 1e-7;", 1);
        EXPECT_LT(tightOscillator, 1e-5) << type;
        EXPECT_LT(tightOscillator, 1e-2 * looseOscillator) << type;
    }
}

// A side x side square of water particles of spacing dx, the first centred at `corner`.
ParticleSet<2> waterSquare(int side, double dx, const Vec<2>& corner, const std::function<Vec<2>(const Vec<2>&)>& velocityAt) {
    ParticleSet<2> fluid("fluid");
    fluid.resize(static_cast<std::size_t>(side * side));
    auto& v = fluid.add(fields::velocity, Vec<2>::Zero());
    fluid.add(fields::density, 1000.0);
    fluid.add(fields::mass, 1000.0 * dx * dx);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const auto k = static_cast<std::size_t>(j * side + i);
            fluid.position[k] = corner + Vec<2>(i * dx, j * dx);
            fluid.globalId[k] = static_cast<std::int64_t>(k);
            v[k] = velocityAt(fluid.position[k]);
        }
    return fluid;
}

// A 12 x 12 block of water in free space, stretching and spinning: pressure, viscosity and
// continuity all act. Returns the positions at t = 8e-3 s after `steps` equal steps.
std::vector<Vec<2>> dropPositions(const std::string& entries, int steps) {
    constexpr double dx = 0.01;
    ParticleSet<2> fluid = waterSquare(12, dx, Vec<2>(-5.5 * dx, -5.5 * dx),
                                       [](const Vec<2>& x) -> Vec<2> { return Vec<2>(-x.x() + 0.5 * x.y(), x.y() - 0.5 * x.x()) * 20.0; });
    ParticleSet<2> walls("walls");
    walls.add(fields::mass, 0.0);
    FluidModels<2> models{WendlandC2<2>(1.3 * dx), TaitEquationOfState(1000.0, 20.0, 7.0, 0.0), LaminarViscosityMorris1997(1e-3),
                          NoDensityDiffusion{}, DensityFormulation::Continuity};
    FluidSystem<2> system(std::move(models), std::move(fluid), std::move(walls), {}, Vec<2>(-1, -1), Vec<2>(1, 1), Vec<2>::Zero(), 0.0);
    auto integrator = makeIntegrator(entries);
    system.evaluateRates(0.0);
    const double endTime = 8e-3, dt = endTime / steps;
    double t = 0.0;
    while (t < endTime - 1e-15) t += integrator->step(system, t, std::min(dt, endTime - t));
    return system.fluid.position;
}

double largestDifference(const std::vector<Vec<2>>& a, const std::vector<Vec<2>>& b) {
    double largest = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, (a[i] - b[i]).norm());
    return largest;
}

class SelfConvergence : public ::testing::TestWithParam<OrderCase> {};

TEST_P(SelfConvergence, ObservedOrderOnASmallDrop) {
    // Differences between successive halvings of the step shrink as 2^order.
    const OrderCase& c = GetParam();
    const auto coarse = dropPositions(c.entries, c.steps);
    const auto medium = dropPositions(c.entries, 2 * c.steps);
    const auto fine = dropPositions(c.entries, 4 * c.steps);
    const double observed = std::log2(largestDifference(coarse, medium) / largestDifference(medium, fine));
    EXPECT_NEAR(observed, c.order, 0.3) << c.entries;
}

// 40 coarse steps: CFL number 0.3 on h/c0. Verlet is second order between Euler steps; the
// Euler steps add a first-order error, still mixed with the second-order one at these step
// counts: with one every 40 steps the observed order falls from 2.3 (40 coarse steps) to 1.5
// (80), with one every step it is 1.7 (40). The ODE test above sees Euler's first order.
INSTANTIATE_TEST_SUITE_P(AllIntegrators, SelfConvergence,
                         ::testing::Values(OrderCase{"type symplectic;", 2, 40}, OrderCase{"type verlet; eulerEvery 1000000;", 2, 40},
                                           OrderCase{"type leapfrog;", 2, 40}, OrderCase{"type predictorCorrector;", 2, 40},
                                           OrderCase{"type arkodeERK; table ARKODE_BOGACKI_SHAMPINE_4_2_3;", 3, 40},
                                           OrderCase{"type arkodeIMEX; table ARK324L2SA;", 3, 40}),
                         caseName);

TEST(IntegratorCounters, NativeIntegratorsCountTheirEvaluations) {
    for (const auto& [entries, perStep] : std::vector<std::pair<std::string, long>>{
             {"type symplectic;", 2}, {"type verlet;", 1}, {"type leapfrog;", 1}, {"type predictorCorrector;", 2}}) {
        auto integrator = makeIntegrator(entries);
        auto system = singleParticle(Vec<2>::Zero(), Vec<2>::Zero(), Vec<2>(0, -1), 0.0);
        for (int k = 0; k < 7; ++k) integrator->step(*system, k * 1e-3, 1e-3);
        const auto counters = integrator->counters();
        ASSERT_GE(counters.size(), 2u);
        EXPECT_EQ(counters[0], (std::pair<std::string, long>{"steps", 7})) << entries;
        EXPECT_EQ(counters[1], (std::pair<std::string, long>{"right-hand-side evaluations", 7 * perStep})) << entries;
    }
}

}  // namespace

namespace {

// A decaying shear wave u_x = U sin(2 pi y) in a periodic unit square, nu = 1: amplitude
// U exp(-nu k^2 t). After `steps` steps of dt: the wave's amplitude and the largest speed (NaN
// if a SUNDIALS integrator stopped on a non-finite rate). A run that blew up is told by its
// largest speed: the growing grid-scale modes can leave the projection on the wave near zero.
struct ShearWave {
    double amplitude;
    double largestSpeed;
};

ShearWave shearWave(const std::string& entries, double dt, int steps, double& exact) {
    constexpr int side = 20;
    constexpr double dx = 1.0 / side, U = 1e-3, nu = 1.0;
    ParticleSet<2> fluid = waterSquare(side, dx, Vec<2>(0.5 * dx, 0.5 * dx),
                                       [](const Vec<2>& x) -> Vec<2> { return Vec<2>(U * std::sin(2.0 * std::numbers::pi * x.y()), 0.0); });
    ParticleSet<2> walls("walls");
    walls.add(fields::mass, 0.0);
    const double h = 1.3 * dx;
    FluidModels<2> models{WendlandC2<2>(h), TaitEquationOfState(1000.0, 1.0, 7.0, 0.0), LaminarViscosityMorris1997(nu), NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    FluidSystem<2> system(std::move(models), std::move(fluid), std::move(walls), {}, Vec<2>(0, 0), Vec<2>(1, 1), Vec<2>::Zero(), 0.0, {true, true});
    auto integrator = makeIntegrator(entries);
    system.evaluateRates(0.0);
    double t = 0.0;
    try {
        for (int k = 0; k < steps; ++k) {
            t += integrator->step(system, t, dt);
            if (system.wrapPeriodic()) integrator->stateChangedOutside();
        }
    } catch (const FatalError&) {
        return {std::nan(""), std::nan("")};  // the SUNDIALS integrators stop on a non-finite rate
    }
    exact = U * std::exp(-nu * 4.0 * std::numbers::pi * std::numbers::pi * t);
    double projection = 0.0, largestSpeed = 0.0;
    for (std::size_t k = 0; k < system.fluid.size(); ++k) {
        projection += system.fluid[fields::velocity][k].x() * std::sin(2.0 * std::numbers::pi * system.fluid.position[k].y());
        largestSpeed = std::max(largestSpeed, system.fluid[fields::velocity][k].norm());
    }
    return {2.0 * projection / static_cast<double>(system.fluid.size()), largestSpeed};
}

}  // namespace

TEST(ImexIntegrator, StableAtTenTimesTheExplicitViscousStep) {
    const double h = 1.3 / 20.0, nu = 1.0;
    const double dt = 10.0 * 0.125 * h * h / nu;  // acoustic CFL number dt c0 / h = 0.08
    double exact = 0.0;
    // The wave's speed is 1e-3: the explicit run must leave it far behind (or stop).
    const double explicitSpeed = shearWave("type symplectic;", dt, 20, exact).largestSpeed;
    EXPECT_FALSE(explicitSpeed < 1.0) << "the explicit integrator should not survive this step: largest speed " << explicitSpeed;
    // The reference: the explicit integrator at half its viscous limit, 20 times more steps.
    const double reference = shearWave("type symplectic;", dt / 20.0, 400, exact).amplitude;
    // The SPH viscous operator at 20 particles per wavelength decays 4.8 % slower than the
    // continuum; the time error is what the IMEX step must keep small.
    EXPECT_NEAR(std::log(reference / 1e-3) / std::log(exact / 1e-3), 1.0, 0.06);
    for (const std::string jacobian : {"differenceQuotient", "velocityBlock"}) {
        const double amplitude = shearWave("type arkodeIMEX; jacobianTimesVector " + jacobian + ";", dt, 20, exact).amplitude;
        EXPECT_NEAR(amplitude / reference, 1.0, 0.01) << jacobian << ": amplitude " << amplitude << ", reference " << reference;
    }
}
