#include "physics/FluidSystem.hpp"
#include "timeIntegrators/SymplecticPositionVerlet.hpp"

#include <gtest/gtest.h>

using namespace sph;

namespace {

FluidSystem<2> singleParticle(const Vec<2>& x, const Vec<2>& v, const Vec<2>& gravity, double rampTime) {
    ParticleSet<2> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = x;
    fluid.addVector("velocity", v);
    fluid.addScalar("density", 1000.0);
    fluid.addScalar("mass", 1.0);
    ParticleSet<2> walls("walls");
    walls.addScalar("mass", 0.0);
    FluidModels<2> models{WendlandC2<2>(0.01), TaitEquationOfState(1000.0, 10.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    return FluidSystem<2>(std::move(models), std::move(fluid), std::move(walls), {}, Vec<2>(-2, -2), Vec<2>(4, 4), gravity, rampTime);
}

}  // namespace

TEST(SymplecticPositionVerlet, ConstantAccelerationIsIntegratedExactly) {
    const Vec<2> x0(0.5, 2.0), v0(1.0, 3.0), g(0.0, -9.81);
    auto system = singleParticle(x0, v0, g, 0.0);
    SymplecticPositionVerlet<2> integrator;
    system.evaluateRates(0.0);
    double t = 0.0;
    for (double dt : {0.01, 0.02, 0.005, 0.03}) {
        integrator.step(system, t, dt);
        t += dt;
    }
    const Vec<2> expected = x0 + v0 * t + 0.5 * g * t * t;
    EXPECT_NEAR((system.fluid.position[0] - expected).norm(), 0.0, 1e-13);
    EXPECT_NEAR((system.fluid.vector("velocity")[0] - (v0 + g * t)).norm(), 0.0, 1e-13);
    EXPECT_EQ(integrator.rateEvaluations(), 8u);
}

TEST(SymplecticPositionVerlet, SecondOrderUnderATimeDependentForce) {
    // The gravity ramp g (sin((t/T - 1/2) pi) + 1)/2 makes the force depend on time:
    // halving the step must cut the error by about 4.
    const auto finalPosition = [](int steps) {
        auto system = singleParticle(Vec<2>::Zero(), Vec<2>::Zero(), Vec<2>(0.0, -1.0), 1.0);
        SymplecticPositionVerlet<2> integrator;
        system.evaluateRates(0.0);
        const double dt = 1.0 / steps;
        for (int k = 0; k < steps; ++k) integrator.step(system, k * dt, dt);
        return system.fluid.position[0].y();
    };
    // y'' = -(sin((t - 1/2) pi) + 1)/2 from rest: y(1) = -1/4 + 1/pi^2.
    const double pi = std::acos(-1.0);
    const double exact = -0.25 + 1.0 / (pi * pi);
    const double coarse = std::abs(finalPosition(20) - exact), fine = std::abs(finalPosition(40) - exact);
    EXPECT_GT(coarse / fine, 3.5);
    EXPECT_LT(coarse / fine, 4.5);
}
