#include "kernels/Kernel.hpp"

#include <type_traits>

namespace sph {

template <int D>
KernelRegistry<D> makeKernelRegistry() {
    const CoefficientDoc hdx{"hdx", "", "smoothing length over particle spacing, h = hdx dx (>= 1)"};
    KernelRegistry<D> registry("kernel");
    [&]<class... Kernels>(std::type_identity<std::variant<Kernels...>>) {
        (registry.add(std::string(Kernels::name), {std::string(Kernels::summary), std::string(Kernels::reference), {hdx}},
                      [](double h) { return Kernel<D>{Kernels(h)}; }),
         ...);
    }(std::type_identity<Kernel<D>>{});
    return registry;
}

template KernelRegistry<1> makeKernelRegistry<1>();
template KernelRegistry<2> makeKernelRegistry<2>();
template KernelRegistry<3> makeKernelRegistry<3>();

}  // namespace sph
