#include "boundaryModels/RepulsiveWall.hpp"
#include "motion/FreeBody2D.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/SymplecticPositionVerlet.hpp"

#include <gtest/gtest.h>

using namespace sph;

namespace {

constexpr double dx = 0.02;

// A body of three wall particles around (1, 1) with one fluid particle at `fluidAt`.
std::unique_ptr<FluidSystem<2>> bodyAndParticle(const Vec<2>& fluidAt, const Vec<2>& gravity) {
    ParticleSet<2> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = fluidAt;
    fluid.add(fields::density, 1000.0);
    fluid.add(fields::mass, 0.4);
    fluid.add(fields::velocity, Vec<2>::Zero());
    ParticleSet<2> walls("walls");
    walls.resize(3);
    walls.position = {Vec<2>(0.98, 1.0), Vec<2>(1.0, 1.0), Vec<2>(1.02, 1.0)};
    walls.add(fields::mass, 0.4);
    walls.add(fields::spacing, dx);
    walls.add(fields::normal, Vec<2>(0, 1));
    walls.add(fields::patch, 0);
    std::vector<Patch<2>> patches(1);
    patches[0].name = "body";
    patches[0].end = 3;
    patches[0].model = std::make_unique<RepulsiveWall<2>>(MonaghanKajtar2009{5.0, dx, 0.0, 0.0});
    patches[0].motion = std::make_unique<FreeBody2D>(Dictionary::fromString("mass 2; momentOfInertia 0.01; centreOfMass (1 1);", "motion"));
    FluidModels<2> models{WendlandC2<2>(1.3 * dx), TaitEquationOfState(1000.0, 10.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    return std::make_unique<FluidSystem<2>>(std::move(models), std::move(fluid), std::move(walls), std::move(patches), Vec<2>(-1, -1), Vec<2>(3, 3),
                                            gravity, 0.0);
}

const FreeBody2D& body(const FluidSystem<2>& s) { return dynamic_cast<const FreeBody2D&>(*s.patches[0].motion); }

}  // namespace

TEST(FreeBody2D, FallsFreelyUnderGravity) {
    auto s = bodyAndParticle(Vec<2>(2.5, 2.5), Vec<2>(0, -9.81));  // the fluid particle is far away
    SymplecticPositionVerlet<2> integrator;
    s->evaluateRates(0.0);
    double t = 0.0;
    for (int k = 0; k < 50; ++k, t += 1e-3) integrator.step(*s, t, 1e-3);
    EXPECT_NEAR(body(*s).state().position.y(), 1.0 - 0.5 * 9.81 * t * t, 1e-12);
    EXPECT_NEAR(s->walls.position[2].y(), 1.0 - 0.5 * 9.81 * t * t, 1e-12);  // the particles follow
    EXPECT_NEAR(s->walls[fields::velocity][2].y(), -9.81 * t, 1e-12);
}

TEST(FreeBody2D, FluidAndBodyExchangeMomentumExactly) {
    // No gravity; the fluid particle sits off-centre above the body, inside the repulsion's
    // range: it is pushed up, the body down and turned, and the total momentum stays zero.
    auto s = bodyAndParticle(Vec<2>(1.015, 1.015), Vec<2>::Zero());
    SymplecticPositionVerlet<2> integrator;
    s->evaluateRates(0.0);
    double t = 0.0;
    for (int k = 0; k < 100; ++k, t += 1e-4) integrator.step(*s, t, 1e-4);
    const Vec<2> fluidMomentum = 0.4 * s->fluid[fields::velocity][0];
    const Vec<2> bodyMomentum = 2.0 * body(*s).state().velocity;
    EXPECT_GT(fluidMomentum.y(), 1e-6);
    EXPECT_LT((fluidMomentum + bodyMomentum).norm(), 1e-12 * fluidMomentum.norm() + 1e-15);
    EXPECT_NE(body(*s).state().angularVelocity, 0.0);
    // The normals turn with the body.
    const double angle = body(*s).state().angle;
    EXPECT_NEAR((s->walls[fields::normal][0] - Vec<2>(-std::sin(angle), std::cos(angle))).norm(), 0.0, 1e-12);
}
