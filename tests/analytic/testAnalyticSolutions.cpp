// The analytic solutions against values generated independently (../shared/reference-data,
// copied here: Morris et al. 1997 series, Taylor-Green decay, Monaghan 1994 drop ODE by RK4 at
// dt 5e-8) and against their limits (steady profiles, t = 0).
#include "analytic/AnalyticSolution.hpp"
#include "analytic/EllipticalDropMonaghan1994.hpp"
#include "io/SelectByType.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using namespace sph;

template <int D = 2>
std::unique_ptr<AnalyticSolution<D>> solution(const std::string& text) {
    const Dictionary dict = Dictionary::fromString(text, "solution");
    return selectByType(makeAnalyticSolutionRegistry<D>(), dict, dict);
}

}  // namespace

TEST(AnalyticSolutions, PoiseuilleMatchesTheGeneratedSeriesAndItsLimits) {
    const auto u = solution("type poiseuille; F 2e-4; L 1e-3; nu 1e-6;");
    // poiseuille_morris1997_analytic_profiles.csv (9 significant digits), y = L/2: t = 0.0225, 0.045, 0.1125 s.
    EXPECT_NEAR(u->velocity(Vec<2>(0.3e-3, 0.5e-3), 0.0225).x(), 4.46547501e-06, 1e-14);
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.5e-3), 0.045).x(), 8.46914111e-06, 1e-13);
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.55e-3), 0.1125).x(), 1.63544747e-05, 1e-13);
    // Steady: u_max = F L^2/(8 nu); at rest at t = 0 (to the series' truncation).
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.5e-3), 100.0).x(), 2.5e-5, 1e-15);
    EXPECT_LT(std::abs(u->velocity(Vec<2>(0.0, 0.3e-3), 0.0).x()), 1e-6 * 2.5e-5);
    EXPECT_EQ(u->velocity(Vec<2>(0.0, 0.3e-3), 0.01).y(), 0.0);
    EXPECT_FALSE(u->hasPressure());
}

TEST(AnalyticSolutions, CouetteMatchesTheGeneratedSeriesAndItsLimits) {
    const auto u = solution("type couette; V0 2.5e-5; L 1e-3; nu 1e-6;");
    // To the file's 9 significant digits.
    // couette_morris1997_analytic_profiles.csv: y = L/2 at t = 0.0225, 0.225 s; y = 0.55 L at 0.045 s.
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.5e-3), 0.0225).x(), 4.60553136e-07, 1e-15);
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.5e-3), 0.225).x(), 1.07725745e-05, 1e-13);
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.55e-3), 0.045).x(), 3.34035411e-06, 1e-14);
    EXPECT_NEAR(u->velocity(Vec<2>(0.0, 0.25e-3), 100.0).x(), 0.25 * 2.5e-5, 1e-16);
}

TEST(AnalyticSolutions, TaylorGreenDecaysAtItsRateAndIsDivergenceFree) {
    const auto tg = solution("type taylorGreen; U 1; L 1; nu 0.01;");
    // taylor_green_2d_analytic_decay.csv, Re 100: max|u| = e^{bt} = 0.454040739 at t = 1, 0.206152992 at t = 2.
    EXPECT_NEAR(tg->velocity(Vec<2>(0.0, 0.25), 1.0).x(), -0.454040739, 1e-9);
    EXPECT_NEAR(tg->velocity(Vec<2>(0.25, 0.0), 2.0).y(), 0.206152992, 1e-9);
    // div u = 0 by central differences at an arbitrary point.
    const Vec<2> x(0.31, 0.77);
    const double e = 1e-6, t = 0.4;
    const double divergence = (tg->velocity(x + Vec<2>(e, 0), t).x() - tg->velocity(x - Vec<2>(e, 0), t).x() + tg->velocity(x + Vec<2>(0, e), t).y() -
                               tg->velocity(x - Vec<2>(0, e), t).y()) /
                              (2 * e);
    EXPECT_NEAR(divergence, 0.0, 1e-8);
    // p = -rho U^2 e^{2bt} (cos 4 pi x + cos 4 pi y)/4: -rho/2 e^{2bt} at the origin.
    EXPECT_NEAR(tg->pressure(Vec<2>::Zero(), 1.0, {1000.0, Vec<2>::Zero()}), -500.0 * 0.206152992, 1e-6);
}

TEST(AnalyticSolutions, EllipticalDropFollowsTheOde) {
    const auto drop = solution("type ellipticalDrop; A0 100; R0 1; centre (1 2);");
    const auto& ode = dynamic_cast<const EllipticalDropMonaghan1994<2>&>(*drop);
    // elliptical_drop_monaghan1994_analytic.csv: t = 0.001 and 0.008 (a = a_minor, A).
    EXPECT_NEAR(ode.at(0.001).ratio, 0.905135812, 1e-8);
    EXPECT_NEAR(ode.at(0.001).rate, 99.0179478, 1e-6);
    EXPECT_NEAR(ode.at(0.008).ratio, 0.500174572, 1e-8);
    EXPECT_NEAR(ode.at(0.008).rate, 68.6205651, 1e-6);
    // Asked again earlier, it integrates afresh.
    EXPECT_NEAR(ode.at(0.001).ratio, 0.905135812, 1e-8);
    // u = -A (x - xc), v = A (y - yc).
    const Vec<2> u = drop->velocity(Vec<2>(1.5, 2.25), 0.0);
    EXPECT_DOUBLE_EQ(u.x(), -50.0);
    EXPECT_DOUBLE_EQ(u.y(), 25.0);
    // Centre pressure (p_centre, rho 1) at t = 0 and 0.008; zero on the ellipse (semi-axes a, 1/a).
    const FlowConstants<2> unit{1.0, Vec<2>::Zero()};
    EXPECT_NEAR(drop->pressure(Vec<2>(1, 2), 0.0, unit), 5000.0, 1e-9);
    EXPECT_NEAR(drop->pressure(Vec<2>(1, 2), 0.008, unit), 1108.63138, 1e-4);
    const double a = ode.at(0.008).ratio;
    EXPECT_NEAR(drop->pressure(Vec<2>(1 + a * std::cos(0.3), 2 + std::sin(0.3) / a), 0.008, unit), 0.0, 1e-9);
}

TEST(AnalyticSolutions, HydrostaticFollowsGravity) {
    const auto still = solution("type hydrostatic; freeSurfaceHeight 0.9;");
    EXPECT_NEAR(still->pressure(Vec<2>(0.3, 0.4), 0.0, {1000.0, Vec<2>(0, -9.81)}), 1000 * 9.81 * 0.5, 1e-9);
    EXPECT_NEAR(still->pressure(Vec<2>(0.4, 0.3), 0.0, {1000.0, Vec<2>(-2, 0)}), 1000 * 2 * (0.9 - 0.4), 1e-9);  // up is +x
    EXPECT_EQ(still->velocity(Vec<2>(0.3, 0.4), 1.0), Vec<2>::Zero());
}

TEST(AnalyticSolutions, UnknownOrWrongDimensionIsAnError) {
    try {
        solution<3>("type taylorGreen; U 1; L 1; nu 0.01;");
        FAIL() << "a 3D Taylor-Green solution was accepted";
    } catch (const FatalError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown analytic solution 'taylorGreen'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("hydrostatic"), std::string::npos) << e.what();
    }
}
