#include "analytic/AnalyticSolution.hpp"

#include "analytic/EllipticalDropMonaghan1994.hpp"
#include "analytic/HydrostaticPressure.hpp"
#include "analytic/PlaneChannelMorris1997.hpp"
#include "analytic/TaylorGreen2D.hpp"

namespace sph {

template <int D>
double AnalyticSolution<D>::pressure(const Vec<D>&, double, const FlowConstants<D>&) const {
    throw FatalError("error: this analytic solution has no pressure field");
}

template <int D>
AnalyticSolutionRegistry<D> makeAnalyticSolutionRegistry() {
    AnalyticSolutionRegistry<D> registry("analytic solution");
    registry.add("hydrostatic", {"still water, p = rho0 |g| (H - z)", "", {{"freeSurfaceHeight", "", "H"}}},
                 [](const Dictionary& dict) -> std::unique_ptr<AnalyticSolution<D>> { return std::make_unique<HydrostaticPressure<D>>(dict); });
    if constexpr (D >= 2) {
        registry.add("poiseuille",
                     {"body-force-driven channel start-up (series)",
                      "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214",
                      {{"F", "", "body force along x"}, {"L", "", "channel width"}, {"nu", "", "kinematic viscosity"}}},
                     [](const Dictionary& dict) -> std::unique_ptr<AnalyticSolution<D>> { return std::make_unique<PoiseuilleMorris1997<D>>(dict); });
        registry.add("couette",
                     {"impulsively started upper plate (series)",
                      "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214",
                      {{"V0", "", "upper plate velocity along x"}, {"L", "", "channel width"}, {"nu", "", "kinematic viscosity"}}},
                     [](const Dictionary& dict) -> std::unique_ptr<AnalyticSolution<D>> { return std::make_unique<CouetteMorris1997<D>>(dict); });
    }
    if constexpr (D == 2) {
        registry.add("taylorGreen",
                     {"decaying vortex on a periodic square",
                      "Taylor & Green, Proc. R. Soc. A 158 (1937) 499",
                      {{"U", "", "velocity scale"}, {"L", "", "side of the square"}, {"nu", "", "kinematic viscosity"}}},
                     [](const Dictionary& dict) -> std::unique_ptr<AnalyticSolution<D>> { return std::make_unique<TaylorGreen2D<D>>(dict); });
        registry.add(
            "ellipticalDrop",
            {"free drop stretched by u = -A x, v = A y (ODE)",
             "Monaghan, J. Comput. Phys. 110 (1994) 399",
             {{"A0", "", "initial rate A(0)"}, {"R0", "", "initial radius"}, {"centre", "(0 0)", "centre of the drop"}}},
            [](const Dictionary& dict) -> std::unique_ptr<AnalyticSolution<D>> { return std::make_unique<EllipticalDropMonaghan1994<D>>(dict); });
    }
    return registry;
}

template class AnalyticSolution<1>;
template class AnalyticSolution<2>;
template class AnalyticSolution<3>;
template AnalyticSolutionRegistry<1> makeAnalyticSolutionRegistry<1>();
template AnalyticSolutionRegistry<2> makeAnalyticSolutionRegistry<2>();
template AnalyticSolutionRegistry<3> makeAnalyticSolutionRegistry<3>();

}  // namespace sph
