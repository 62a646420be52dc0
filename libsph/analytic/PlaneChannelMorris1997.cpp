#include "analytic/PlaneChannelMorris1997.hpp"

#include <cmath>
#include <numbers>

namespace sph {

namespace {

constexpr int maximumTerms = 10000;
constexpr double negligibleTerm = 1e-16;

}  // namespace

template <int D>
PoiseuilleMorris1997<D>::PoiseuilleMorris1997(const Dictionary& dict)
    : force_(dict.get<double>("F")), width_(dict.getPositive("L")), nu_(dict.getPositive("nu")) {}

template <int D>
Vec<D> PoiseuilleMorris1997<D>::velocity(const Vec<D>& x, double t) const {
    const double pi = std::numbers::pi, y = x[1], L = width_;
    double u = force_ / (2.0 * nu_) * y * (L - y);
    const double steady = std::abs(force_) * L * L / (8.0 * nu_);
    for (int n = 0; n < maximumTerms; ++n) {
        const double k = 2.0 * n + 1.0;
        const double term = 4.0 * force_ * L * L / (nu_ * pi * pi * pi * k * k * k) * std::exp(-k * k * pi * pi * nu_ * t / (L * L));
        u -= term * std::sin(k * pi * y / L);
        if (std::abs(term) < negligibleTerm * steady) break;
    }
    Vec<D> velocity = Vec<D>::Zero();
    velocity[0] = u;
    return velocity;
}

template <int D>
CouetteMorris1997<D>::CouetteMorris1997(const Dictionary& dict)
    : plateVelocity_(dict.get<double>("V0")), width_(dict.getPositive("L")), nu_(dict.getPositive("nu")) {}

template <int D>
Vec<D> CouetteMorris1997<D>::velocity(const Vec<D>& x, double t) const {
    const double pi = std::numbers::pi, y = x[1], L = width_;
    double u = plateVelocity_ * y / L;
    for (int n = 1; n < maximumTerms; ++n) {
        const double term = 2.0 * plateVelocity_ / (n * pi) * std::exp(-n * n * pi * pi * nu_ * t / (L * L));
        u += (n % 2 == 0 ? term : -term) * std::sin(n * pi * y / L);
        if (std::abs(term) < negligibleTerm * std::abs(plateVelocity_)) break;
    }
    Vec<D> velocity = Vec<D>::Zero();
    velocity[0] = u;
    return velocity;
}

template class PoiseuilleMorris1997<2>;
template class PoiseuilleMorris1997<3>;
template class CouetteMorris1997<2>;
template class CouetteMorris1997<3>;

}  // namespace sph
