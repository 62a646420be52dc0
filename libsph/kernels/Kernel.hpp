// The kernel family: every kernel a case can select, as one variant the hot loops are
// instantiated over (std::visit once per stage, never per pair).
#pragma once

#include "core/Registry.hpp"
#include "kernels/CubicSplineMonaghanLattanzio1985.hpp"
#include "kernels/QuinticSplineMorris1997.hpp"
#include "kernels/WendlandC2.hpp"
#include "kernels/WendlandC4.hpp"

#include <variant>

namespace sph {

template <int D>
using Kernel = std::variant<CubicSplineMonaghanLattanzio1985<D>, QuinticSplineMorris1997<D>, WendlandC2<D>, WendlandC4<D>>;

// Whether this build compiled the hot loops for a kernel (CMake option SPHKIT_KERNELS).
template <class K>
inline constexpr bool compiledKernel = false;
#ifdef SPHKIT_KERNEL_cubicSpline
template <int D>
inline constexpr bool compiledKernel<CubicSplineMonaghanLattanzio1985<D>> = true;
#endif
#ifdef SPHKIT_KERNEL_quinticSpline
template <int D>
inline constexpr bool compiledKernel<QuinticSplineMorris1997<D>> = true;
#endif
#ifdef SPHKIT_KERNEL_wendlandC2
template <int D>
inline constexpr bool compiledKernel<WendlandC2<D>> = true;
#endif
#ifdef SPHKIT_KERNEL_wendlandC4
template <int D>
inline constexpr bool compiledKernel<WendlandC4<D>> = true;
#endif
inline constexpr const char* compiledKernelNames = SPHKIT_COMPILED_KERNELS;

// Factory argument: the smoothing length h.
template <int D>
using KernelRegistry = Registry<Kernel<D>, double>;

template <int D>
KernelRegistry<D> makeKernelRegistry();

}  // namespace sph
