#include "densityDiffusion/DensityDiffusion.hpp"

namespace sph {

template <int D>
DensityDiffusionRegistry<D> makeDensityDiffusionRegistry() {
    DensityDiffusionRegistry<D> registry("densityDiffusion");
    registerEach(registry);
    return registry;
}

template DensityDiffusionRegistry<1> makeDensityDiffusionRegistry<1>();
template DensityDiffusionRegistry<2> makeDensityDiffusionRegistry<2>();
template DensityDiffusionRegistry<3> makeDensityDiffusionRegistry<3>();

}  // namespace sph
