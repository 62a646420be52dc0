#include "boundaryModels/DummyParticlesAdami2012.hpp"
#include "boundaryModels/DynamicBoundaryCrespo2007.hpp"
#include "boundaryModels/ModifiedDynamicBoundaryEnglish2022.hpp"
#include "physics/FluidSystem.hpp"

#include "support/BlockDomain.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>

using namespace sph;

namespace {

constexpr double dx = 0.02, rho0 = 1000.0, g = 9.81, H = 0.5;

// Fluid at rest in hydrostatic equilibrium above y = 0, three wall layers below it, the walls
// accelerating at `wallAcceleration`.
FluidSystem<2> hydrostaticColumn(std::unique_ptr<BoundaryModel<2>> model, const Vec<2>& wallAcceleration = Vec<2>::Zero()) {
    const TaitEquationOfState eos(rho0, 20.0, 7.0, 0.0);
    ParticleSet<2> fluid("fluid");
    const int nx = 20, ny = 25;
    fluid.resize(nx * ny);
    auto& rho = fluid.add(fields::density, rho0);
    fluid.add(fields::mass, rho0 * dx * dx);
    fluid.add(fields::velocity, Vec<2>::Zero());
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const std::size_t k = static_cast<std::size_t>(j * nx + i);
            fluid.position[k] = {(i + 0.5) * dx, (j + 0.5) * dx};
            rho[k] = eos.density(rho0 * g * (H - fluid.position[k].y()));
        }
    ParticleSet<2> walls("walls");
    walls.resize(3 * nx);
    walls.add(fields::mass, rho0 * dx * dx);
    walls.add(fields::normal, Vec<2>(0.0, 1.0));
    walls.add(fields::patch, 0);
    walls.add(fields::acceleration, wallAcceleration, false);
    walls.add(fields::spacing, dx);
    auto& layers = walls.add(fields::layer, 0);
    for (int layer = 0; layer < 3; ++layer)
        for (int i = 0; i < nx; ++i) {
            walls.position[static_cast<std::size_t>(layer * nx + i)] = {(i + 0.5) * dx, -(layer + 0.5) * dx};
            layers[static_cast<std::size_t>(layer * nx + i)] = layer;
        }
    std::vector<Patch<2>> patches(1);
    patches[0].name = "floor";
    patches[0].begin = 0;
    patches[0].end = walls.size();
    patches[0].model = std::move(model);
    FluidModels<2> models{WendlandC2<2>(1.3 * dx), eos, NoViscosity{}, NoDensityDiffusion{}, DensityFormulation::Continuity};
    return FluidSystem<2>(std::move(models), std::move(fluid), std::move(walls), std::move(patches), Vec<2>(-0.1, -0.1), Vec<2>(0.5, 0.6),
                          Vec<2>(0.0, -g), 0.0);
}

// Dummy particles from a patch entry, in a case whose viscosity is artificial or not.
std::unique_ptr<BoundaryModel<2>> dummyParticles(const std::string& entry, bool artificialViscosity = false) {
    ModelContext context{dx, 1.3 * dx, 20.0, rho0, 0.0, rho0 * 400.0 / 7.0, 7.0};
    context.artificialViscosity = artificialViscosity;
    return std::make_unique<DummyParticlesAdami2012<2>>(Dictionary::fromString(entry, "constant/boundaryProperties"), context);
}

// The viscous velocity of the first wall layer under the column sliding along it at speed U.
Vec<2> viscousWallVelocity(std::unique_ptr<BoundaryModel<2>> model) {
    constexpr double U = 0.5;
    auto system = hydrostaticColumn(std::move(model));
    system.walls.add(fields::viscousVelocity, Vec<2>::Zero(), false);
    for (auto& v : system.fluid[fields::velocity]) v = Vec<2>(U, 0.0);
    system.evaluateRates(0.0);
    return system.walls[fields::viscousVelocity][10] / U;  // a first-layer particle mid-floor
}

// Wall density rates under a disordered block of fluid with random velocities, three wall
// layers with their own velocities, computed with two threads, against the direct sum over
// every fluid particle: in 3D (pairs in vector lanes) and in 2D across a periodic side.
template <int D>
void compareWallDensityRatesWithDirectSum(bool periodicX) {
    const std::size_t perSide = D == 2 ? 16 : 8;
    const double period = static_cast<double>(perSide) * dx;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    ParticleSet<D> fluid("fluid");
    std::size_t count = 1;
    for (int d = 0; d < D; ++d) count *= perSide;
    fluid.resize(count);
    fluid.add(fields::density, rho0);
    auto& m = fluid.add(fields::mass, rho0 * std::pow(dx, D));
    auto& v = fluid.add(fields::velocity, Vec<D>::Zero());
    for (std::size_t k = 0; k < count; ++k) {
        std::size_t rest = k;
        for (int d = 0; d < D; ++d) {
            fluid.position[k][d] = (static_cast<double>(rest % perSide) + 0.5 + 0.3 * unit(random)) * dx;
            rest /= perSide;
            v[k][d] = unit(random);
        }
        m[k] *= 1.0 + 0.05 * unit(random);
    }
    ParticleSet<D> walls("walls");
    const std::size_t perLayer = count / perSide;
    walls.resize(3 * perLayer);
    walls.add(fields::mass, rho0 * std::pow(dx, D));
    walls.add(fields::normal, Vec<D>::Unit(D - 1));
    walls.add(fields::patch, 0);
    for (std::size_t w = 0; w < walls.size(); ++w) {
        std::size_t rest = w % perLayer;
        for (int d = 0; d + 1 < D; ++d) {
            walls.position[w][d] = (static_cast<double>(rest % perSide) + 0.5) * dx;
            rest /= perSide;
        }
        walls.position[w][D - 1] = -(0.5 + static_cast<double>(w / perLayer)) * dx;
    }
    std::vector<Patch<D>> patches(1);
    patches[0] = {"floor", 0, walls.size(), std::make_unique<DynamicBoundaryCrespo2007<D>>(), std::nullopt, nullptr};
    const auto domain = test::blockDomain<D>(period, periodicX);
    const WendlandC2<D> kernel(1.3 * dx);
    FluidModels<D> models{kernel, TaitEquationOfState(rho0, 20.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{}, DensityFormulation::Continuity};
    FluidSystem<D> system(std::move(models), std::move(fluid), std::move(walls), std::move(patches), domain.min, domain.max, Vec<D>::Zero(), 0.0,
                          domain.periodic);
    auto& wallVelocity = system.walls[fields::velocity];
    for (auto& velocity : wallVelocity)
        for (int d = 0; d < D; ++d) velocity[d] = 0.2 * unit(random);
    omp_set_num_threads(2);
    system.evaluateRates(0.0);
    omp_set_num_threads(omp_get_num_procs());

    const auto& x = system.fluid.position;
    const auto& vFluid = system.fluid[fields::velocity];
    const auto& mFluid = system.fluid[fields::mass];
    double worst = 0.0, scale = 0.0;
    for (std::size_t w = 0; w < system.walls.size(); ++w) {
        double rate = 0.0;  // sum_f m_f (v_w - v_f) . grad_w W_wf
        for (std::size_t f = 0; f < x.size(); ++f) {
            Vec<D> r = system.walls.position[w] - x[f];
            if (periodicX) r[0] -= period * std::round(r[0] / period);
            if (r.norm() < 2.0 * 1.3 * dx) rate += mFluid[f] * kernel.gradientFactor(r.norm()) * (wallVelocity[w] - vFluid[f]).dot(r);
        }
        worst = std::max(worst, std::abs(system.walls[fields::densityRate][w] - rate));
        scale = std::max(scale, std::abs(rate));
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(worst, 1e-12 * scale) << D << "D, periodic " << periodicX;
}

}  // namespace

TEST(DummyParticlesAdami2012, ExtrapolatesTheHydrostaticPressureLinearlyIntoTheWall) {
    auto system = hydrostaticColumn(dummyParticles(""));
    system.evaluateRates(0.0);
    const auto& p = system.walls[fields::pressure];
    // Away from the side edges the fluid pressure is exactly linear, so the extrapolation is
    // exact up to the small density variation (Tait, c0 = 20: rho varies by 1.2 %).
    for (std::size_t w = 0; w < system.walls.size(); ++w) {
        const Vec<2>& x = system.walls.position[w];
        if (x.x() < 0.06 || x.x() > 0.34) continue;
        if (x.y() < 0.5 * dx - system.supportRadius()) continue;  // beyond every fluid particle's reach
        EXPECT_NEAR(p[w], rho0 * g * (H - x.y()), 0.015 * rho0 * g * H) << "wall particle at " << x.transpose();
    }
    // The inverse equation of state gives the wall density.
    const auto& rhoWall = system.walls[fields::density];
    EXPECT_NEAR(rhoWall[0], TaitEquationOfState(rho0, 20.0, 7.0, 0.0).density(p[0]), 1e-9);
}

TEST(DummyParticlesAdami2012, WallAccelerationEntersTheExtrapolation) {
    // Walls falling with gravity (a_w = g): the hydrostatic term vanishes and the wall pressure
    // is the kernel-weighted mean of the fluid pressure around it, below the linear extrapolation.
    auto falling = hydrostaticColumn(dummyParticles(""), Vec<2>(0.0, -g));
    falling.evaluateRates(0.0);
    auto fixed = hydrostaticColumn(dummyParticles(""));
    fixed.evaluateRates(0.0);
    const std::size_t w = 10;  // first layer, middle
    const auto& pFalling = falling.walls[fields::pressure];
    const auto& pFixed = fixed.walls[fields::pressure];
    // The difference is exactly the hydrostatic term g . sum_f rho_f (x_w - x_f) W_wf / sum_f W_wf.
    const WendlandC2<2> kernel(1.3 * dx);
    const Vec<2>& xw = fixed.walls.position[w];
    double weight = 0.0, moment = 0.0;
    for (std::size_t f = 0; f < fixed.fluid.size(); ++f) {
        const double r = (xw - fixed.fluid.position[f]).norm();
        if (r >= fixed.supportRadius()) continue;
        const double W = kernel.value(r);
        weight += W;
        moment += fixed.fluid[fields::density][f] * g * (fixed.fluid.position[f].y() - xw.y()) * W;
    }
    EXPECT_NEAR(pFixed[w] - pFalling[w], moment / weight, 1e-9 * rho0 * g * H);
    EXPECT_GT(pFixed[w] - pFalling[w], 0.5 * rho0 * g * dx);
}

TEST(DummyParticlesAdami2012, HoldsTheColumnAgainstGravity) {
    auto system = hydrostaticColumn(dummyParticles(""));
    system.evaluateRates(0.0);
    // The walls must complete the support as if the fluid continued below: the bottom row then
    // feels what a row with full fluid support feels (the bulk scheme's own residual, here
    // about 0.06 g from the lattice moment and the compressibility at c0 = 20), not the
    // deficiency of a free edge (of order g).
    const auto& a = system.fluid[fields::acceleration];
    const std::size_t nx = 20, bulkRow = 4;  // 4 dx up: beyond the wall's reach (support 2.6 dx)
    for (std::size_t i = 5; i < 15; ++i) EXPECT_NEAR(a[i].y(), a[bulkRow * nx + i].y(), 0.01 * g) << "column " << i;
}

// v~ is the Shepard mean of a uniform velocity, U itself: free slip passes it on, no slip mirrors
// it about the (fixed) wall's velocity, 2 * 0 - U.
TEST(DummyParticlesAdami2012, NoSlipMirrorsTheFluidVelocityFreeSlipPassesItOn) {
    EXPECT_NEAR((viscousWallVelocity(dummyParticles("noSlip yes;")) - Vec<2>(-1.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((viscousWallVelocity(dummyParticles("noSlip no;")) - Vec<2>(1.0, 0.0)).norm(), 0.0, 1e-12);
}

// The default follows the viscosity: no slip with a physical one, free slip with artificial
// viscosity, where a mirrored velocity brakes impacts; asking for no slip there is kept and warned of.
TEST(DummyParticlesAdami2012, FreeSlipByDefaultOnlyWithArtificialViscosity) {
    EXPECT_NEAR((viscousWallVelocity(dummyParticles("")) - Vec<2>(-1.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((viscousWallVelocity(dummyParticles("", true)) - Vec<2>(1.0, 0.0)).norm(), 0.0, 1e-12);
    testing::internal::CaptureStdout();
    const auto quiet = dummyParticles("noSlip no;", true);
    const auto asked = dummyParticles("clampNegativePressure yes;\nnoSlip yes;", true);
    const std::string printed = testing::internal::GetCapturedStdout();
    EXPECT_EQ(printed.rfind("constant/boundaryProperties:2:1: warning: keyword 'noSlip'", 0), 0u) << printed;
    EXPECT_NE(printed.find("noSlip no, the default with artificial viscosity"), std::string::npos) << printed;
    EXPECT_EQ(printed.find('\n'), printed.size() - 1) << "one warning: " << printed;
    EXPECT_NEAR((viscousWallVelocity(dummyParticles("noSlip yes;", true)) - Vec<2>(-1.0, 0.0)).norm(), 0.0, 1e-12);
}

TEST(DynamicBoundaryCrespo2007, WallDensityRateFromApproachingFluid) {
    const TaitEquationOfState eos(rho0, 20.0, 7.0, 0.0);
    ParticleSet<2> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = {0.0, 0.015};
    fluid.add(fields::density, rho0);
    fluid.add(fields::mass, 0.4);
    fluid.add(fields::velocity, Vec<2>(0.0, -2.0));
    ParticleSet<2> walls("walls");
    walls.resize(1);
    walls.position[0] = {0.0, 0.0};
    walls.add(fields::mass, 0.4);
    walls.add(fields::density, 1005.0);
    std::vector<Patch<2>> patches(1);
    patches[0] = {"floor", 0, 1, std::make_unique<DynamicBoundaryCrespo2007<2>>(), std::nullopt, nullptr};
    const WendlandC2<2> kernel(1.3 * dx);
    FluidModels<2> models{kernel, eos, NoViscosity{}, NoDensityDiffusion{}, DensityFormulation::Continuity};
    FluidSystem<2> system(std::move(models), std::move(fluid), std::move(walls), std::move(patches), Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1),
                          Vec<2>::Zero(), 0.0);
    ASSERT_TRUE(system.wallDensityEvolves());
    system.evaluateRates(0.0);
    // d rho_w/dt = m_f (v_w - v_f) . grad_w W = m_f F(r) (v_w - v_f) . (x_w - x_f)
    const double expected = 0.4 * kernel.gradientFactor(0.015) * Vec<2>(0.0, 2.0).dot(Vec<2>(0.0, -0.015));
    EXPECT_GT(expected, 0.0);
    EXPECT_NEAR(system.walls[fields::densityRate][0], expected, 1e-12 * std::abs(expected));
    EXPECT_NEAR(system.walls[fields::pressure][0], eos.pressure(1005.0), 1e-9);
}

TEST(DynamicBoundaryCrespo2007, WallDensityRatesEqualTheDirectSum) {
    compareWallDensityRatesWithDirectSum<3>(false);
    compareWallDensityRatesWithDirectSum<2>(true);
    compareWallDensityRatesWithDirectSum<2>(false);
}

TEST(ModifiedDynamicBoundaryEnglish2022, ExtrapolatesALinearDensityExactlyIntoEveryLayer) {
    // First-order consistency: a density linear in x and y reaches every wall particle exactly,
    // at the column's side edges too, where the ghost nodes see fluid on one side only.
    auto system = hydrostaticColumn(std::make_unique<ModifiedDynamicBoundaryEnglish2022<2>>(Dictionary::fromString("", "tank")));
    const auto linear = [](const Vec<2>& x) { return rho0 * (1.0 + 0.02 * (H - x.y()) / H + 0.01 * x.x() / H); };
    auto& rhoFluid = system.fluid[fields::density];
    for (std::size_t f = 0; f < system.fluid.size(); ++f) rhoFluid[f] = linear(system.fluid.position[f]);
    system.evaluateRates(0.0);
    const auto& rhoWall = system.walls[fields::density];
    const auto& pWall = system.walls[fields::pressure];
    const TaitEquationOfState eos(rho0, 20.0, 7.0, 0.0);
    for (std::size_t w = 0; w < system.walls.size(); ++w) {
        EXPECT_NEAR(rhoWall[w], linear(system.walls.position[w]), 1e-9 * rho0) << "wall particle at " << system.walls.position[w].transpose();
        EXPECT_NEAR(pWall[w], eos.pressure(rhoWall[w]), 1e-9 * rho0 * g * H);
    }
}

namespace {

// One fluid particle above two wall particles, the second beyond its reach.
FluidSystem<2> oneFluidParticleOverAWall(bool wallsHaveLayers) {
    ParticleSet<2> fluid("fluid");
    fluid.resize(1);
    fluid.position[0] = {0.0, 0.02};
    fluid.add(fields::density, 1010.0);
    fluid.add(fields::mass, 0.4);
    fluid.add(fields::velocity, Vec<2>::Zero());
    ParticleSet<2> walls("walls");
    walls.resize(2);
    walls.position[0] = {0.0, -0.5 * dx};
    walls.position[1] = {0.5, -0.5 * dx};
    walls.add(fields::mass, 0.4);
    walls.add(fields::spacing, dx);
    walls.add(fields::normal, Vec<2>(0.0, 1.0));
    if (wallsHaveLayers) walls.add(fields::layer, 0);
    std::vector<Patch<2>> patches(1);
    patches[0] = {"floor", 0, 2, std::make_unique<ModifiedDynamicBoundaryEnglish2022<2>>(Dictionary::fromString("", "tank")), std::nullopt, nullptr};
    FluidModels<2> models{WendlandC2<2>(1.3 * dx), TaitEquationOfState(rho0, 20.0, 7.0, 0.0), NoViscosity{}, NoDensityDiffusion{},
                          DensityFormulation::Continuity};
    return FluidSystem<2>(std::move(models), std::move(fluid), std::move(walls), std::move(patches), Vec<2>(-0.1, -0.1), Vec<2>(0.6, 0.1),
                          Vec<2>::Zero(), 0.0);
}

}  // namespace

TEST(ModifiedDynamicBoundaryEnglish2022, TakesTheShepardDensityWhereTheGhostNodeSeesTooLittleFluid) {
    // One fluid particle: the first-order system is singular, so rho_w = m W / (V W) = rho_f;
    // the second wall particle's ghost node sees no fluid: rho0.
    auto system = oneFluidParticleOverAWall(true);
    EXPECT_FALSE(system.wallDensityEvolves());
    system.evaluateRates(0.0);
    EXPECT_NEAR(system.walls[fields::density][0], 1010.0, 1e-9);
    EXPECT_EQ(system.walls[fields::density][1], rho0);
    EXPECT_EQ(system.walls[fields::pressure][1], 0.0);
}

TEST(ModifiedDynamicBoundaryEnglish2022, RefusesWallsWithoutLayers) {
    try {
        auto system = oneFluidParticleOverAWall(false);
        system.evaluateRates(0.0);
        FAIL() << "no error for walls without layers";
    } catch (const FatalError& e) {
        EXPECT_NE(std::string(e.what()).find("needs the wall field 'layer'"), std::string::npos) << e.what();
    }
}

TEST(ModifiedDynamicBoundaryEnglish2022, ReachesTheFluidAroundItsDeepestGhostNode) {
    // What a decomposed run's halo must hold: the third layer, 2.5 dx deep, mirrors its ghost
    // node 5 dx into the fluid, which reads the fluid within the support of it.
    auto system = hydrostaticColumn(std::make_unique<ModifiedDynamicBoundaryEnglish2022<2>>(Dictionary::fromString("", "tank")));
    const double support = system.supportRadius();
    EXPECT_NEAR(system.patches[0].model->reach(support), 5.0 * dx + support, 1e-15);
}

TEST(ModifiedDynamicBoundaryEnglish2022, HoldsTheColumnAgainstGravity) {
    // As the dummy particles above: the bottom row feels what the bulk feels.
    auto system = hydrostaticColumn(std::make_unique<ModifiedDynamicBoundaryEnglish2022<2>>(Dictionary::fromString("", "tank")));
    system.evaluateRates(0.0);
    const auto& a = system.fluid[fields::acceleration];
    const std::size_t nx = 20, bulkRow = 4;
    for (std::size_t i = 5; i < 15; ++i) EXPECT_NEAR(a[i].y(), a[bulkRow * nx + i].y(), 0.01 * g) << "column " << i;
}
