#include "analytic/TaylorGreen2D.hpp"

#include <cmath>
#include <numbers>

namespace sph {

template <int D>
TaylorGreen2D<D>::TaylorGreen2D(const Dictionary& dict)
    : speed_(dict.get<double>("U")),
      side_(dict.getPositive("L")),
      decayRate_(-8.0 * std::numbers::pi * std::numbers::pi * dict.getNonNegative("nu") / (side_ * side_)) {}

template <int D>
Vec<D> TaylorGreen2D<D>::velocity(const Vec<D>& x, double t) const {
    const double k = 2.0 * std::numbers::pi / side_, amplitude = speed_ * std::exp(decayRate_ * t);
    return Vec<D>(-amplitude * std::cos(k * x[0]) * std::sin(k * x[1]), amplitude * std::sin(k * x[0]) * std::cos(k * x[1]));
}

template <int D>
double TaylorGreen2D<D>::pressure(const Vec<D>& x, double t, const FlowConstants<D>& constants) const {
    const double k = 2.0 * std::numbers::pi / side_;
    return -constants.rho0 * speed_ * speed_ * std::exp(2.0 * decayRate_ * t) * (std::cos(2.0 * k * x[0]) + std::cos(2.0 * k * x[1])) / 4.0;
}

template class TaylorGreen2D<2>;

}  // namespace sph
