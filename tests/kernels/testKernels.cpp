// Property tests run over every kernel in every dimension: normalisation, consistency of the
// gradient with the value, compact support, zero gradient sum on a full lattice.
#include "core/Vector.hpp"
#include "kernels/Kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <tuple>
#include <variant>

namespace {

template <class K, int Dim>
struct KernelCase {
    using Kernel = K;
    static constexpr int D = Dim;
};

template <class T>
class KernelProperties : public ::testing::Test {};

// Every kernel of the family (kernels/Kernel.hpp) in 1D, 2D and 3D.
template <int D, class Family>
struct CasesOf;
template <int D, class... Kernels>
struct CasesOf<D, std::variant<Kernels...>> {
    using type = std::tuple<KernelCase<Kernels, D>...>;
};
template <class... Lists>
struct TypesOf;
template <class... In1, class... In2, class... In3>
struct TypesOf<std::tuple<In1...>, std::tuple<In2...>, std::tuple<In3...>> {
    using type = ::testing::Types<In1..., In2..., In3...>;
};
using AllKernels = TypesOf<CasesOf<1, sph::Kernel<1>>::type, CasesOf<2, sph::Kernel<2>>::type, CasesOf<3, sph::Kernel<3>>::type>::type;
TYPED_TEST_SUITE(KernelProperties, AllKernels);

// Integral of W over space by the radial measure (2, 2 pi r, 4 pi r^2), Simpson's rule.
template <class K, int D>
double integral(const K& kernel) {
    const int n = 20000;
    const double R = kernel.supportRadius();
    const double step = R / n;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double r = k * step;
        const double measure = D == 1 ? 2.0 : (D == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r);
        const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        sum += weight * measure * kernel.value(r);
    }
    return sum * step / 3.0;
}

}  // namespace

TYPED_TEST(KernelProperties, IntegratesToOne) {
    using K = typename TypeParam::Kernel;
    for (double h : {0.1, 1.0, 3.0}) {
        EXPECT_NEAR((integral<K, TypeParam::D>(K(h))), 1.0, 1e-6) << "h = " << h;
    }
}

TYPED_TEST(KernelProperties, VanishesAtAndBeyondTheSupportRadius) {
    using K = typename TypeParam::Kernel;
    const K kernel(0.7);
    const double R = kernel.supportRadius();
    EXPECT_LT(kernel.value(R), 1e-14 * kernel.value(0.0));  // q = R/h rounds to just below its bound
    EXPECT_EQ(kernel.value(1.5 * R), 0.0);
    EXPECT_EQ(kernel.gradientFactor(R * (1 + 1e-12)), 0.0);
    EXPECT_GT(kernel.value(0.999 * R), 0.0);
    EXPECT_GT(kernel.value(0.0), kernel.value(0.5 * R));
}

TYPED_TEST(KernelProperties, GradientFactorIsDerivativeOverRadius) {
    using K = typename TypeParam::Kernel;
    const K kernel(0.5);
    const double R = kernel.supportRadius();
    for (double fraction : {0.05, 0.2, 0.33, 0.5, 0.51, 0.7, 0.9}) {
        const double r = fraction * R, e = 1e-6 * R;
        const double derivative = (kernel.value(r + e) - kernel.value(r - e)) / (2 * e);
        EXPECT_NEAR(kernel.gradientFactor(r) * r, derivative, 1e-6 * std::abs(kernel.value(0.0) / R)) << "r = " << r;
        EXPECT_LT(kernel.gradientFactor(r), 0.0);
    }
}

TYPED_TEST(KernelProperties, LatticeSumsAreOneAndGradientsCancel) {
    // On a full lattice, sum_j V W_ij ~ 1 and sum_j V grad W_ij = 0 by symmetry, for any offset of i.
    using K = typename TypeParam::Kernel;
    constexpr int D = TypeParam::D;
    const double dx = 0.1;
    const K kernel(1.3 * dx);
    const int reach = static_cast<int>(std::ceil(kernel.supportRadius() / dx)) + 1;
    const double volume = std::pow(dx, D);
    sph::Vec<D> sumGradient = sph::Vec<D>::Zero();
    double sumValue = 0.0;
    std::array<int, 3> index{};
    const int count = 2 * reach + 1;
    const int total = static_cast<int>(std::pow(count, D));
    for (int flat = 0; flat < total; ++flat) {
        int rest = flat;
        sph::Vec<D> r;
        for (int d = 0; d < D; ++d) {
            index[static_cast<std::size_t>(d)] = rest % count - reach;
            rest /= count;
            r[d] = index[static_cast<std::size_t>(d)] * dx;
        }
        sumValue += volume * kernel.value(r.norm());
        sumGradient += volume * kernel.gradientFactor(r.norm()) * r;
    }
    EXPECT_NEAR(sumValue, 1.0, 0.02);
    EXPECT_LT(sumGradient.norm(), 1e-12);
}

TYPED_TEST(KernelProperties, NormalisationScalesAsInverseLengthToTheDimension) {
    using K = typename TypeParam::Kernel;
    const K a(1.0), b(2.0);
    EXPECT_NEAR(a.value(0.0) / b.value(0.0), std::pow(2.0, TypeParam::D), 1e-12);
}

TEST(WendlandC6, ValuesAtHalfTheSupportAsDehnenAndAlyNormaliseThem) {
    // s = 1/2 at r = h: (1-s)^8 (1 + 8s + 25s^2 + 32s^3) = 15.25/256, (1-s)^7 (1 + 7s + 19s^2 + 21s^3) = 11.875/128;
    // sigma = 55/64 (1D), 39/(14 pi) (2D), 1365/(512 pi) (3D) at h = 1.
    const double pi = std::numbers::pi;
    EXPECT_NEAR(sph::WendlandC6<1>(1.0).value(1.0), 55.0 / 64.0 * 11.875 / 128.0, 1e-15);
    EXPECT_NEAR(sph::WendlandC6<2>(1.0).value(1.0), 39.0 / (14.0 * pi) * 15.25 / 256.0, 1e-15);
    EXPECT_NEAR(sph::WendlandC6<3>(1.0).value(1.0), 1365.0 / (512.0 * pi) * 15.25 / 256.0, 1e-15);
}
