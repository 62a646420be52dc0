#include "densityDiffusion/DensityDiffusion.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
DensityDiffusionRegistry<D> makeDensityDiffusionRegistry() {
    const CoefficientDoc delta{"delta", "0.1", "diffusion coefficient"};
    DensityDiffusionRegistry<D> registry("densityDiffusion");
    registry.add("none", {"no density diffusion", "", {}},
                 [](const Dictionary&, const ModelContext&) { return DensityDiffusion<D>{NoDensityDiffusion{}}; });
    registry.add("molteniColagrossi",
                 {"delta-SPH diffusion of density differences", "Molteni & Colagrossi, Comput. Phys. Commun. 180 (2009) 861", {delta}},
                 [](const Dictionary& dict, const ModelContext& c) {
                     return DensityDiffusion<D>{MolteniColagrossi2009(dict.getNonNegativeOrDefault("delta", 0.1), c.h, c.c0)};
                 });
    registry.add(
        "fourtakas", {"diffusion of the dynamic density (hydrostatic part removed)", "Fourtakas et al., Comput. Fluids 190 (2019) 346", {delta}},
        [](const Dictionary& dict, const ModelContext& c) {
            return DensityDiffusion<D>{Fourtakas2019<D>(dict.getNonNegativeOrDefault("delta", 0.1), c.h, c.c0, c.rho0, c.stiffness, c.exponent)};
        });
    registry.add("antuono",
                 {"delta-SPH diffusion with the renormalised density gradient (a hydrostatic gradient is not diffused)",
                  "Antuono et al., Comput. Phys. Commun. 181 (2010) 532; Marrone et al., CMAME 200 (2011) 1526",
                  {delta}},
                 [](const Dictionary& dict, const ModelContext& c) {
                     return DensityDiffusion<D>{Antuono2010(dict.getNonNegativeOrDefault("delta", 0.1), c.h, c.c0)};
                 });
    return registry;
}

template <int D>
std::string describe(const DensityDiffusion<D>& diffusion) {
    return std::visit(
        [](const auto& d) -> std::string {
            using T = std::decay_t<decltype(d)>;
            if constexpr (std::is_same_v<T, NoDensityDiffusion>)
                return "none";
            else if constexpr (std::is_same_v<T, MolteniColagrossi2009>)
                return fmt::format("molteniColagrossi: delta {:g}", d.delta);
            else if constexpr (std::is_same_v<T, Antuono2010>)
                return fmt::format("antuono: delta {:g}", d.delta);
            else
                return fmt::format("fourtakas: delta {:g}", d.delta);
        },
        diffusion);
}

template DensityDiffusionRegistry<1> makeDensityDiffusionRegistry<1>();
template DensityDiffusionRegistry<2> makeDensityDiffusionRegistry<2>();
template DensityDiffusionRegistry<3> makeDensityDiffusionRegistry<3>();
template std::string describe<1>(const DensityDiffusion<1>&);
template std::string describe<2>(const DensityDiffusion<2>&);
template std::string describe<3>(const DensityDiffusion<3>&);

}  // namespace sph
