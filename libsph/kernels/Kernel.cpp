#include "kernels/Kernel.hpp"

namespace sph {

template <int D>
KernelRegistry<D> makeKernelRegistry() {
    const CoefficientDoc hdx{"hdx", "", "smoothing length over particle spacing, h = hdx dx (>= 1)"};
    KernelRegistry<D> registry("kernel");
    registry.add("cubicSpline", {"cubic B-spline, support 2h", "Monaghan & Lattanzio, A&A 149 (1985) 135", {hdx}},
                 [](double h) { return Kernel<D>{CubicSplineMonaghanLattanzio1985<D>(h)}; });
    registry.add("quinticSpline", {"quintic spline, support 3h", "Morris, Fox & Zhu, J. Comput. Phys. 136 (1997) 214", {hdx}},
                 [](double h) { return Kernel<D>{QuinticSplineMorris1997<D>(h)}; });
    registry.add("wendlandC2", {"Wendland C2, support 2h", "Wendland, Adv. Comput. Math. 4 (1995) 389", {hdx}},
                 [](double h) { return Kernel<D>{WendlandC2<D>(h)}; });
    registry.add("wendlandC4", {"Wendland C4, support 2h", "Wendland, Adv. Comput. Math. 4 (1995) 389", {hdx}},
                 [](double h) { return Kernel<D>{WendlandC4<D>(h)}; });
    return registry;
}

template KernelRegistry<1> makeKernelRegistry<1>();
template KernelRegistry<2> makeKernelRegistry<2>();
template KernelRegistry<3> makeKernelRegistry<3>();

}  // namespace sph
