// The kernel family: every kernel a case can select, as one variant the hot loops are
// instantiated over (std::visit once per stage, never per pair). A kernel is one header that
// meets SmoothingKernel (its name, summary and reference, its support and values) and one
// entry in the variant below: the registry, `-listModels` and the tests read it from there.
#pragma once

#include "core/Registry.hpp"
#include "kernels/CubicSplineMonaghanLattanzio1985.hpp"
#include "kernels/QuinticSplineMorris1997.hpp"
#include "kernels/WendlandC2.hpp"
#include "kernels/WendlandC4.hpp"
#include "kernels/WendlandC6.hpp"

#include <algorithm>
#include <concepts>
#include <string_view>
#include <type_traits>
#include <variant>

namespace sph {

template <int D>
using Kernel = std::variant<CubicSplineMonaghanLattanzio1985<D>, QuinticSplineMorris1997<D>, WendlandC2<D>, WendlandC4<D>, WendlandC6<D>>;

// What a kernel offers: built from the smoothing length h; W(r) and the gradient factor
// (dW/dr)/r, both zero from the support radius on; its registry name and documentation.
template <class K>
concept SmoothingKernel = std::constructible_from<K, double> && requires(const K kernel, double r) {
    { K::name } -> std::convertible_to<std::string_view>;
    { K::summary } -> std::convertible_to<std::string_view>;
    { K::reference } -> std::convertible_to<std::string_view>;
    { kernel.supportRadius() } -> std::same_as<double>;
    { kernel.value(r) } -> std::same_as<double>;
    { kernel.gradientFactor(r) } -> std::same_as<double>;
    { kernel.h } -> std::convertible_to<double>;
};

template <class Family>
inline constexpr bool allSmoothingKernels = false;
template <class... Kernels>
inline constexpr bool allSmoothingKernels<std::variant<Kernels...>> = (SmoothingKernel<Kernels> && ...);
static_assert(allSmoothingKernels<Kernel<1>> && allSmoothingKernels<Kernel<2>> && allSmoothingKernels<Kernel<3>>);

// The kernels whose hot loops this build compiled (CMake option SPHKIT_KERNELS): "all", or
// their names separated by spaces.
inline constexpr std::string_view compiledKernelNames = SPHKIT_COMPILED_KERNELS;

// True when `holds` is true of every name in a list of names separated by spaces.
template <class Predicate>
constexpr bool everyName(std::string_view list, Predicate holds) {
    for (std::size_t begin = 0; begin < list.size();) {
        const std::size_t end = std::min(list.find(' ', begin), list.size());
        if (!holds(list.substr(begin, end - begin))) return false;
        begin = end + 1;
    }
    return true;
}

template <class K>
inline constexpr bool compiledKernel =
    compiledKernelNames == "all" || !everyName(compiledKernelNames, [](std::string_view name) { return name != K::name; });

// Every name SPHKIT_KERNELS lists is a kernel of the family: a misspelt one stops the build.
template <class... Kernels>
constexpr bool namesAKernel(std::string_view name, std::type_identity<std::variant<Kernels...>>) {
    return ((Kernels::name == name) || ...);
}
constexpr bool everyCompiledKernelExists() {
    return compiledKernelNames == "all" ||
           everyName(compiledKernelNames, [](std::string_view name) { return namesAKernel(name, std::type_identity<Kernel<3>>{}); });
}
static_assert(everyCompiledKernelExists(), "SPHKIT_KERNELS names a kernel that kernels/Kernel.hpp does not list");

// Factory argument: the smoothing length h.
template <int D>
using KernelRegistry = Registry<Kernel<D>, double>;

template <int D>
KernelRegistry<D> makeKernelRegistry();

}  // namespace sph
