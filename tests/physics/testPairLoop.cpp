// The symmetric pair loop (each fluid pair once, per-thread accumulators) against a direct
// O(N^2) sum of every term written out here from the papers' formulas: a disordered block of
// fluid with random velocities and densities, pressure + continuity + artificial viscosity +
// Fourtakas diffusion (its series and its std::pow form), and the terms of two layers of wall
// particles under it, in 2D and 3D, with one and two threads, with and without a periodic side.
#include "physics/FluidSystem.hpp"

#include "support/BlockDomain.hpp"

#include <Eigen/LU>
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

namespace {

using namespace sph;

template <int D>
struct Scene {
    double dx = 0.02, h = 1.3 * 0.02, rho0 = 1000.0, c0 = 20.0, gamma = 7.0, alpha = 0.1, delta = 0.1;
    Vec<D> gravity = Vec<D>::Unit(D - 1) * -9.81;
    int perSide = D == 2 ? 24 : 10;
};

template <int D>
ParticleSet<D> disorderedBlock(const Scene<D>& s, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    ParticleSet<D> fluid("fluid");
    std::size_t count = 1;
    for (int d = 0; d < D; ++d) count *= static_cast<std::size_t>(s.perSide);
    fluid.resize(count);
    auto& rho = fluid.add(fields::density, s.rho0);
    auto& m = fluid.add(fields::mass, s.rho0 * std::pow(s.dx, D));
    auto& v = fluid.add(fields::velocity, Vec<D>::Zero());
    for (std::size_t k = 0; k < count; ++k) {
        std::size_t rest = k;
        for (int d = 0; d < D; ++d) {
            fluid.position[k][d] = (static_cast<double>(rest % static_cast<std::size_t>(s.perSide)) + 0.5 + 0.3 * unit(random)) * s.dx;
            rest /= static_cast<std::size_t>(s.perSide);
            v[k][d] = 0.5 * unit(random);
        }
        rho[k] = s.rho0 * (1.0 + 0.01 * unit(random));
        m[k] *= 1.0 + 0.05 * unit(random);
        fluid.globalId[k] = static_cast<std::int64_t>(k);
    }
    return fluid;
}

// Two layers of wall particles under the block (last coordinate -dx/2 and -3dx/2).
template <int D>
ParticleSet<D> wallLayers(const Scene<D>& s) {
    ParticleSet<D> walls("walls");
    std::size_t perLayer = 1;
    for (int d = 0; d + 1 < D; ++d) perLayer *= static_cast<std::size_t>(s.perSide);
    walls.resize(2 * perLayer);
    auto& m = walls.add(fields::mass, s.rho0 * std::pow(s.dx, D));
    for (std::size_t w = 0; w < walls.size(); ++w) {
        std::size_t rest = w % perLayer;
        for (int d = 0; d + 1 < D; ++d) {
            walls.position[w][d] = (static_cast<double>(rest % static_cast<std::size_t>(s.perSide)) + 0.5) * s.dx;
            rest /= static_cast<std::size_t>(s.perSide);
        }
        walls.position[w][D - 1] = -(0.5 + static_cast<double>(w / perLayer)) * s.dx;
        m[w] *= 1.0 + 0.1 * static_cast<double>(w % 3);
        walls.globalId[w] = static_cast<std::int64_t>(w);
    }
    return walls;
}

// With periodicX, the block's x extent is the period: pairs and wall pairs across it count.
// With antuono, the diffusion is delta-SPH's with the renormalised density gradient instead of Fourtakas'.
template <int D>
void compareWithDirectSum(int threads, double c0 = Scene<D>{}.c0, bool periodicX = false, bool antuono = false) {
    Scene<D> s;
    s.c0 = c0;
    const double period = s.perSide * s.dx;
    const auto domain = test::blockDomain<D>(period, periodicX);
    const auto separation = [&](const Vec<D>& a, const Vec<D>& b) {
        Vec<D> r = a - b;
        if (periodicX) r[0] -= period * std::round(r[0] / period);
        return r;
    };
    const WendlandC2<D> kernel(s.h);
    const TaitEquationOfState eos(s.rho0, s.c0, s.gamma, 0.0);
    const DensityDiffusion<D> diffusion = antuono ? DensityDiffusion<D>(Antuono2010(s.delta, s.h, s.c0))
                                                  : DensityDiffusion<D>(Fourtakas2019<D>(s.delta, s.h, s.c0, s.rho0, eos.B, s.gamma));
    FluidModels<D> models{kernel, eos, ArtificialViscosityMonaghan1992(s.alpha, 0.0, s.h, s.c0), diffusion, DensityFormulation::Continuity};
    FluidSystem<D> system(std::move(models), disorderedBlock(s, 17), wallLayers(s), {}, domain.min, domain.max, s.gravity, 0.0, domain.periodic);
    // Wall particles with their own pressure, density, velocity and viscous velocity (no
    // boundary model here sets them).
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (std::size_t w = 0; w < system.walls.size(); ++w) {
        system.walls[fields::pressure][w] = 2000.0 * (1.0 + unit(random));
        system.walls[fields::density][w] = s.rho0 * (1.0 + 0.01 * unit(random));
        for (int d = 0; d < D; ++d) {
            system.walls[fields::velocity][w][d] = 0.2 * unit(random);
            system.walls[fields::viscousVelocity][w][d] = 0.5 * unit(random);
        }
    }
    omp_set_num_threads(threads);
    system.evaluateRates(1.0);
    omp_set_num_threads(omp_get_num_procs());

    const auto& x = system.fluid.position;
    const auto& v = system.fluid[fields::velocity];
    const auto& m = system.fluid[fields::mass];
    const auto& rho = system.fluid[fields::density];
    const double radius = 2.0 * s.h, eta2 = 0.01 * s.h * s.h;
    // Antuono et al.: <grad rho>^L_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j, L_i the inverse of
    // sum_j V_j (x_j - x_i) (x) grad_i W_ij (unrenormalised where its determinant is below 0.1).
    std::vector<Vec<D>> gradient(x.size(), Vec<D>::Zero());
    for (std::size_t i = 0; antuono && i < x.size(); ++i) {
        Eigen::Matrix<double, D, D> moment = Eigen::Matrix<double, D, D>::Zero();
        Vec<D> sum = Vec<D>::Zero();
        for (std::size_t j = 0; j < x.size(); ++j) {
            const Vec<D> r = separation(x[i], x[j]);
            if (j == i || r.norm() >= radius) continue;
            const Vec<D> gradW = kernel.gradientFactor(r.norm()) * r;
            moment += (m[j] / rho[j]) * (-r) * gradW.transpose();
            sum += (rho[j] - rho[i]) * (m[j] / rho[j]) * gradW;
        }
        gradient[i] = moment.determinant() > 0.1 ? Vec<D>(moment.inverse() * sum) : sum;
    }
    double worstAcceleration = 0.0, worstRate = 0.0, scaleAcceleration = 0.0, scaleRate = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        Vec<D> a = s.gravity;
        double drho = 0.0;
        const double pi = eos.pressure(rho[i]);
        for (std::size_t j = 0; j < x.size(); ++j) {
            const Vec<D> r = separation(x[i], x[j]);
            const double distance = r.norm();
            if (j == i || distance >= radius) continue;
            const Vec<D> gradW = kernel.gradientFactor(distance) * r;
            const Vec<D> vij = v[i] - v[j];
            const double pj = eos.pressure(rho[j]);
            a -= m[j] * (pi / (rho[i] * rho[i]) + pj / (rho[j] * rho[j])) * gradW;
            const double vr = vij.dot(r);
            if (vr < 0.0) {  // Monaghan (1992)
                const double mu = s.h * vr / (r.squaredNorm() + eta2);
                a -= m[j] * (-s.alpha * s.c0 * mu / (0.5 * (rho[i] + rho[j]))) * gradW;
            }
            drho += m[j] * vij.dot(gradW);
            if (antuono) {  // psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / (r^2 + eta^2) - (<grad rho>_i + <grad rho>_j)
                const Vec<D> psi = 2.0 * (rho[j] - rho[i]) * (-r) / (r.squaredNorm() + eta2) - (gradient[i] + gradient[j]);
                drho += s.delta * s.h * s.c0 * psi.dot(gradW) * m[j] / rho[j];
            } else {  // Fourtakas et al. (2019): rho^H_ji = rho0 [(1 - rho0 g.r_ij / B)^(1/gamma) - 1]
                const double hydrostatic = s.rho0 * (std::pow(1.0 - s.rho0 * s.gravity.dot(r) / eos.B, 1.0 / s.gamma) - 1.0);
                drho += 2.0 * s.delta * s.h * s.c0 * ((rho[i] - rho[j]) + hydrostatic) * r.dot(gradW) / (r.squaredNorm() + eta2) * m[j] / rho[j];
            }
        }
        const auto& walls = system.walls;
        for (std::size_t w = 0; w < walls.size(); ++w) {  // pressure, viscosity and continuity; no diffusion
            const Vec<D> r = separation(x[i], walls.position[w]);
            const double distance = r.norm();
            if (distance >= radius) continue;
            const Vec<D> gradW = kernel.gradientFactor(distance) * r;
            const double mw = walls[fields::mass][w], pw = walls[fields::pressure][w], rhow = walls[fields::density][w];
            a -= mw * (pi / (rho[i] * rho[i]) + pw / (rhow * rhow)) * gradW;
            const double vr = (v[i] - walls[fields::viscousVelocity][w]).dot(r);
            if (vr < 0.0) {
                const double mu = s.h * vr / (r.squaredNorm() + eta2);
                a -= mw * (-s.alpha * s.c0 * mu / (0.5 * (rho[i] + rhow))) * gradW;
            }
            drho += mw * (v[i] - walls[fields::velocity][w]).dot(gradW);
        }
        worstAcceleration = std::max(worstAcceleration, (system.fluid[fields::acceleration][i] - a).norm());
        worstRate = std::max(worstRate, std::abs(system.fluid[fields::densityRate][i] - drho));
        scaleAcceleration = std::max(scaleAcceleration, a.norm());
        scaleRate = std::max(scaleRate, std::abs(drho));
    }
    EXPECT_LT(worstAcceleration, 1e-11 * scaleAcceleration) << D << "D, " << threads << " threads, periodic " << periodicX;
    EXPECT_LT(worstRate, 1e-11 * scaleRate) << D << "D, " << threads << " threads, periodic " << periodicX;
    EXPECT_GT(scaleRate, 0.0);
}

template <class Viscosity>
concept HasPairFactor = requires(const Viscosity& viscosity) {
    viscosity.pairFactor(0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
};

}  // namespace

TEST(PairLoop, EqualsTheDirectSumIn2D) {
    compareWithDirectSum<2>(1);
    compareWithDirectSum<2>(2);
}

TEST(PairLoop, EqualsTheDirectSumIn3D) {
    compareWithDirectSum<3>(1);
    compareWithDirectSum<3>(2);
}

// c0 = 3 m/s: |y| up to 7 g 2h / c0^2 = 0.40, beyond Fourtakas' series: the loop that uses std::pow.
TEST(PairLoop, EqualsTheDirectSumBeyondFourtakasSeries) {
    compareWithDirectSum<2>(2, 3.0);
    compareWithDirectSum<3>(1, 3.0);
}

// The loop lists candidates without the nearest-image term where no direction is periodic:
// here its other version, across a periodic side.
TEST(PairLoop, EqualsTheDirectSumAcrossAPeriodicSide) {
    compareWithDirectSum<2>(2, Scene<2>{}.c0, true);
    compareWithDirectSum<3>(1, Scene<3>{}.c0, true);
}

TEST(PairLoop, EqualsTheDirectSumWithDeltaSphDiffusion) {
    compareWithDirectSum<2>(1, Scene<2>{}.c0, false, true);
    compareWithDirectSum<2>(2, Scene<2>{}.c0, true, true);
    compareWithDirectSum<3>(2, Scene<3>{}.c0, false, true);
}

// A linear density field (a hydrostatic stratification) is not diffused by delta-SPH's term in
// the interior nor at a free surface, where the renormalised gradient is still exact; Molteni &
// Colagrossi's term diffuses it wherever the sums are one-sided.
TEST(PairLoop, DeltaSphLeavesALinearDensityFieldAlone) {
    const auto rateAtTheTop = [](const DensityDiffusion<2>& diffusion) {
        Scene<2> s;
        ParticleSet<2> fluid("fluid");
        fluid.resize(static_cast<std::size_t>(s.perSide * s.perSide));
        auto& rho = fluid.add(fields::density, s.rho0);
        fluid.add(fields::mass, s.rho0 * s.dx * s.dx);
        fluid.add(fields::velocity, Vec<2>::Zero());
        for (int k = 0; k < s.perSide * s.perSide; ++k) {
            const auto i = static_cast<std::size_t>(k);
            fluid.position[i] = Vec<2>((k % s.perSide + 0.5) * s.dx, (k / s.perSide + 0.5) * s.dx);
            rho[i] = s.rho0 * (1.0 + 0.01 * (1.0 - fluid.position[i].y()));
            fluid.globalId[i] = k;
        }
        const auto domain = test::blockDomain<2>(s.perSide * s.dx, false);
        FluidModels<2> models{WendlandC2<2>(s.h), TaitEquationOfState(s.rho0, s.c0, s.gamma, 0.0), NoViscosity{}, diffusion,
                              DensityFormulation::Continuity};
        ParticleSet<2> walls("walls");
        walls.add(fields::mass, 0.0);
        FluidSystem<2> system(std::move(models), std::move(fluid), std::move(walls), {}, domain.min, domain.max, Vec<2>::Zero(), 0.0,
                              domain.periodic);
        system.evaluateRates(0.0);
        double top = 0.0, interior = 0.0;
        for (std::size_t i = 0; i < system.fluid.size(); ++i) {
            const Vec<2>& x = system.fluid.position[i];
            const double rate = std::abs(system.fluid[fields::densityRate][i]);
            if (x.x() > 0.2 && x.x() < 0.28 && x.y() > 0.46) top = std::max(top, rate);                           // the top row, mid-width
            if (x.x() > 0.2 && x.x() < 0.28 && x.y() > 0.2 && x.y() < 0.28) interior = std::max(interior, rate);  // full support
        }
        return std::pair(top, interior);
    };
    const Scene<2> s;
    const auto [deltaTop, deltaInterior] = rateAtTheTop(Antuono2010(s.delta, s.h, s.c0));
    const auto [molteniTop, molteniInterior] = rateAtTheTop(MolteniColagrossi2009(s.delta, s.h, s.c0));
    EXPECT_GT(molteniTop, 1.0);  // kg/m^3/s: the stratification diffuses at the surface
    // What remains is the regularisation's: the first term carries r^2 / (r^2 + 0.01 h^2), the
    // gradients' part does not, so a nearest pair keeps 0.01 h^2 / (dx^2 + 0.01 h^2) = 1.7 % of it.
    EXPECT_LT(deltaTop, 0.02 * molteniTop);
    EXPECT_LT(deltaInterior, 0.02 * molteniTop);
    EXPECT_LT(molteniInterior, 1e-3 * molteniTop);  // a symmetric lattice cancels it inside to first order (V_j = m / rho_j varies)
}

TEST(PairLoop, FourtakasSeriesEqualsPowWhereItHolds) {
    const double rho0 = 1000.0, B = 20.0 * 20.0 * rho0 / 7.0;
    Fourtakas2019<2> diffusion(0.1, 0.02, 20.0, rho0, B, 7.0);
    diffusion.setGravity(Vec<2>(0.0, -9.81), 0.04);  // |y| <= 6.9e-5: the series
    ASSERT_TRUE(diffusion.seriesHolds);
    for (double y : {-0.0199, -1e-3, -3e-6, 0.0, 2e-7, 5e-4, 0.0199}) {
        const double exact = rho0 * (std::pow(1.0 + y, 1.0 / 7.0) - 1.0);
        const double exactMinus = rho0 * (std::pow(1.0 - y, 1.0 / 7.0) - 1.0);
        double atY = 0.0, atMinusY = 0.0;
        diffusion.hydrostaticDensities(y, atY, atMinusY);
        EXPECT_NEAR(atY, exact, 4e-16 * rho0 + 1e-14 * std::abs(exact)) << y;
        EXPECT_NEAR(atMinusY, exactMinus, 4e-16 * rho0 + 1e-14 * std::abs(exactMinus)) << y;
    }
    diffusion.setGravity(Vec<2>(0.0, -9.81), 10.0);  // |y| up to 0.017 * 10 / 0.04: beyond it, std::pow
    EXPECT_FALSE(diffusion.seriesHolds);
    double atY = 0.0, atMinusY = 0.0;
    diffusion.beyondSeries().hydrostaticDensities(0.3, atY, atMinusY);
    EXPECT_DOUBLE_EQ(atY, rho0 * (std::pow(1.3, 1.0 / 7.0) - 1.0));
    EXPECT_DOUBLE_EQ(atMinusY, rho0 * (std::pow(0.7, 1.0 / 7.0) - 1.0));
}

// Monaghan (1992) by hand, with the quadratic (beta) term the direct sums above leave at 0:
// h = 0.02, v.r = -0.3, r^2 = 4e-4: mu = h v.r / (r^2 + 0.01 h^2) = -14.8514851...,
// Pi = (-alpha c0 mu + beta mu^2) / rho_bar = (29.70297 + 44.11332) / 1005 = 0.0734490473,
// and the pair factor is -Pi F. A receding pair (v.r > 0) gets none.
TEST(PairLoop, ArtificialViscosityPairFactorByHand) {
    const ArtificialViscosityMonaghan1992 viscosity(0.1, 0.2, 0.02, 20.0);
    const double r2 = 4e-4, inverseRegularisedR2 = 1.0 / (r2 + 0.01 * 0.02 * 0.02), F = -5.0;
    EXPECT_NEAR(viscosity.pairFactor(-0.3, r2, inverseRegularisedR2, 1000.0, 1010.0, F), 0.3672452364196077, 1e-15);
    EXPECT_EQ(viscosity.pairFactor(0.3, r2, inverseRegularisedR2, 1000.0, 1010.0, F), 0.0);
}

TEST(PairLoop, InviscidSceneAllocatesAndEvaluatesNoViscousTerm) {
    // No viscous term can be evaluated: NoViscosity has no pair factor for the loop to call.
    static_assert(!HasPairFactor<NoViscosity>);
    static_assert(HasPairFactor<ArtificialViscosityMonaghan1992> && HasPairFactor<LaminarViscosityMorris1997>);
    const Scene<2> s;
    const auto build = [&](Viscosity viscosity) {
        ParticleSet<2> walls("walls");
        walls.add(fields::mass, 0.0);
        FluidModels<2> models{WendlandC2<2>(s.h), TaitEquationOfState(s.rho0, s.c0, s.gamma, 0.0), viscosity, NoDensityDiffusion{},
                              DensityFormulation::Continuity};
        return std::make_unique<FluidSystem<2>>(std::move(models), disorderedBlock(s, 3), std::move(walls), std::vector<Patch<2>>{},
                                                Vec<2>::Constant(-0.1), Vec<2>::Constant(1.0), s.gravity, 0.0);
    };
    const auto inviscid = build(NoViscosity{});
    inviscid->evaluateRates(0.0);
    // The loop's copies: no density (read by viscosity and diffusion only), no viscous wall velocity.
    EXPECT_TRUE(inviscid->cellOrderedFluid().density.empty());
    EXPECT_TRUE(inviscid->cellOrderedFluid().volume.empty());
    EXPECT_FALSE(inviscid->walls.has(fields::viscousVelocity));
    const auto viscous = build(ArtificialViscosityMonaghan1992(s.alpha, 0.0, s.h, s.c0));
    viscous->evaluateRates(0.0);
    EXPECT_EQ(viscous->cellOrderedFluid().density.size(), viscous->fluid.size());
    EXPECT_GT(viscous->cellOrderedFluid().bytes(), inviscid->cellOrderedFluid().bytes());
}
