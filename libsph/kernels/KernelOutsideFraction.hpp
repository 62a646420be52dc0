// The fraction of a kernel's support behind a surface, from the surface alone: by the
// divergence theorem with the field F(r) = -Psi(|r|) r/|r|, Psi(r) = r^(1-D) int_r^R W(s) s^(D-1) ds
// (div F = W away from the kernel's centre, F = 0 beyond the support R), the kernel's
// integral over a region V not holding the centre x_i is the flux through its boundary:
//   int_V W(|y - x_i|) dy = sum_j A_j Psi(|r_ij|) (r_ij . n_j) / |r_ij|,   r_ij = x_i - x_j,
// over surface elements j of area A_j and unit normal n_j pointing out of V (into the fluid).
// The deficiency correction takes V as the space behind the wall: the volume fraction of
// virtual particles (1 - gamma_i of Ferrand et al. 2013, here from the wall particles' areas).
// Any radial function f that vanishes beyond R integrates the same way with f in place of W: the
// correction's no-slip wall takes the laminar viscosity's f(s) = s W'(s)/(s^2 + 0.01 h^2).
// int_r^R f(s) s^(D-1) ds is tabulated once (Simpson's rule, 2048 intervals) and interpolated.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace sph {

template <int D>
class KernelOutsideFraction {
public:
    KernelOutsideFraction() = default;
    template <class Kernel>
    explicit KernelOutsideFraction(const Kernel& kernel)
        : KernelOutsideFraction(kernel.supportRadius(), [&kernel](double s) { return kernel.value(s); }) {}
    template <class RadialFunction>
    KernelOutsideFraction(double support, const RadialFunction& f) : support_(support), step_(support_ / intervals) {
        const auto integrand = [&](double s) { return f(s) * std::pow(s, D - 1); };
        tail_.assign(intervals + 1, 0.0);
        for (int k = intervals - 1; k >= 0; --k) {
            const double a = k * step_, b = a + step_;
            tail_[static_cast<std::size_t>(k)] =
                tail_[static_cast<std::size_t>(k) + 1] + step_ / 6.0 * (integrand(a) + 4.0 * integrand(0.5 * (a + b)) + integrand(b));
        }
        // Psi(r)/r^D against r^2, for elementPerAreaAndHeight.
        const double squareStep = support_ * support_ / squareIntervals;
        inverseSquareStep_ = 1.0 / squareStep;
        perDistanceToTheD_.resize(squareIntervals + 1);
        for (int k = 0; k <= squareIntervals; ++k) {
            const double distance = std::sqrt(std::max(k, 1) * squareStep);
            perDistanceToTheD_[static_cast<std::size_t>(k)] = tailAt(distance) / distanceToTheD(distance);
        }
    }

    // The flux term of one surface element: A_j Psi(|r|) (r . n_j)/|r|, with rDotN = r . n_j.
    double element(double distance, double rDotN, double area) const { return area * tailAt(distance) * rDotN / distanceToTheD(distance); }

    // Psi(|r|)/|r|^D, element() per unit area and unit r . n_j, from |r|^2 in a table of its own
    // (8192 intervals in r^2): no square root or division per call, for the sums over many
    // points of an element (the correction's no-slip stress). Within the first interval, |r| below
    // R/90, it takes the value at the interval's end.
    double elementPerAreaAndHeight(double distanceSquared) const {
        const double u = std::clamp(distanceSquared * inverseSquareStep_, 1.0, static_cast<double>(squareIntervals));
        const auto k = std::min(static_cast<std::size_t>(u), static_cast<std::size_t>(squareIntervals - 1));
        return perDistanceToTheD_[k] + (u - static_cast<double>(k)) * (perDistanceToTheD_[k + 1] - perDistanceToTheD_[k]);
    }

private:
    // int_r^R f(s) s^(D-1) ds, interpolated.
    double tailAt(double distance) const {
        const double u = std::min(distance / step_, static_cast<double>(intervals));
        const auto k = std::min(static_cast<std::size_t>(u), static_cast<std::size_t>(intervals - 1));
        return tail_[k] + (u - static_cast<double>(k)) * (tail_[k + 1] - tail_[k]);
    }

    // |r|^D by multiplication: std::pow of a double took a tenth of a 3D run with the correction.
    static double distanceToTheD(double distance) {
        double power = distance;
        for (int d = 1; d < D; ++d) power *= distance;
        return power;
    }

    static constexpr int intervals = 2048, squareIntervals = 8192;
    double support_ = 0.0, step_ = 1.0, inverseSquareStep_ = 1.0;
    std::vector<double> tail_, perDistanceToTheD_;
};

}  // namespace sph
