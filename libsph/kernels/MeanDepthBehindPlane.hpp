// The mean depth behind a plane of a radial function's integral over the half space beyond it,
// for a centre at height z in front of the plane:
//   delta(z) = int_{behind} f(|y - x|) depth(y) dy / int_{behind} f(|y - x|) dy,
// with both integrals written through the plane integral P(t) of f at distance t from the centre,
//   M0(z) = int_z^R P(t) dt,  M1(z) = int_z^R (t - z) P(t) dt,  delta = M1 / M0,
//   P(t) = f(t) (1D), 2 int_0^sqrt(R^2 - t^2) f(sqrt(x^2 + t^2)) dx (2D), 2 pi int_t^R f(s) s ds (3D).
// The deficiency correction's no-slip wall reads it: a velocity that grows linearly with depth
// behind the wall, sampled by f, acts as its value at this mean depth, which makes the virtual
// particles' viscous sum exact for a linear shear flow past a flat wall. Tabulated once
// (2048 intervals in z, 256 across the plane in 2D) and interpolated; 0 at and beyond R.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace sph {

template <int D>
class MeanDepthBehindPlane {
public:
    MeanDepthBehindPlane() = default;
    template <class RadialFunction>
    MeanDepthBehindPlane(double support, const RadialFunction& f) : step_(support / intervals) {
        std::vector<double> plane(intervals + 1);
        for (int k = 0; k <= intervals; ++k) plane[static_cast<std::size_t>(k)] = planeIntegral(f, support, k * step_);
        // Cumulative trapezoidal sums from R down: int_z^R P and int_z^R t P.
        std::vector<double> zeroth(intervals + 1, 0.0), first(intervals + 1, 0.0);
        for (int k = intervals - 1; k >= 0; --k) {
            const auto at = static_cast<std::size_t>(k);
            const double a = k * step_, b = a + step_;
            zeroth[at] = zeroth[at + 1] + 0.5 * step_ * (plane[at] + plane[at + 1]);
            first[at] = first[at + 1] + 0.5 * step_ * (a * plane[at] + b * plane[at + 1]);
        }
        depth_.assign(intervals + 1, 0.0);
        for (int k = 0; k < intervals; ++k) {
            const auto at = static_cast<std::size_t>(k);
            if (std::abs(zeroth[at]) > 1e-12 * std::abs(zeroth[0])) depth_[at] = (first[at] - k * step_ * zeroth[at]) / zeroth[at];
        }
    }

    // delta at height z in front of the plane (a centre behind it is taken at the plane).
    double operator()(double z) const {
        const double u = std::clamp(z / step_, 0.0, static_cast<double>(intervals));
        const auto k = std::min(static_cast<std::size_t>(u), static_cast<std::size_t>(intervals - 1));
        return depth_[k] + (u - static_cast<double>(k)) * (depth_[k + 1] - depth_[k]);
    }

private:
    template <class RadialFunction>
    static double planeIntegral(const RadialFunction& f, double support, double t) {
        if constexpr (D == 1) {
            return f(t);
        } else {
            constexpr int across = 256;
            const double extent = D == 2 ? std::sqrt(std::max(support * support - t * t, 0.0)) : support - t;
            if (!(extent > 0.0)) return 0.0;
            const double h = extent / across;
            // Simpson's rule over x in [0, extent] (2D: f at sqrt(x^2 + t^2)) or s in [t, R] (3D: f(s) s).
            const auto integrand = [&](double x) { return D == 2 ? f(std::sqrt(x * x + t * t)) : f(t + x) * (t + x); };
            double sum = integrand(0.0) + integrand(extent);
            for (int k = 1; k < across; ++k) sum += (k % 2 == 1 ? 4.0 : 2.0) * integrand(k * h);
            return (D == 2 ? 2.0 : 2.0 * std::numbers::pi) * sum * h / 3.0;
        }
    }

    static constexpr int intervals = 2048;
    double step_ = 1.0;
    std::vector<double> depth_;
};

}  // namespace sph
