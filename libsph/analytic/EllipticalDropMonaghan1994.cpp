#include "analytic/EllipticalDropMonaghan1994.hpp"

#include <algorithm>
#include <cmath>

namespace sph {

template <int D>
EllipticalDropMonaghan1994<D>::EllipticalDropMonaghan1994(const Dictionary& dict)
    : centre_(dict.found("centre") ? dict.getVector<D>("centre") : Vec<D>::Zero()),
      initialRate_(dict.getPositive("A0")),
      radius_(dict.getPositive("R0")),
      cached_{initialRate_, 1.0} {}

template <int D>
typename EllipticalDropMonaghan1994<D>::State EllipticalDropMonaghan1994<D>::at(double t) const {
    if (t < cachedTime_) {
        cachedTime_ = 0.0;
        cached_ = {initialRate_, 1.0};
    }
    const auto rates = [](const State& s) {
        const double a4 = std::pow(s.ratio, 4);
        return State{s.rate * s.rate * (a4 - 1.0) / (a4 + 1.0), -s.ratio * s.rate};
    };
    const auto advance = [&](const State& s, const State& k, double h) { return State{s.rate + h * k.rate, s.ratio + h * k.ratio}; };
    const double maximumStep = 1e-3 / initialRate_;
    while (cachedTime_ < t) {
        const double h = std::min(maximumStep, t - cachedTime_);
        const State k1 = rates(cached_);
        const State k2 = rates(advance(cached_, k1, h / 2));
        const State k3 = rates(advance(cached_, k2, h / 2));
        const State k4 = rates(advance(cached_, k3, h));
        cached_.rate += h / 6 * (k1.rate + 2 * k2.rate + 2 * k3.rate + k4.rate);
        cached_.ratio += h / 6 * (k1.ratio + 2 * k2.ratio + 2 * k3.ratio + k4.ratio);
        cachedTime_ += h;
    }
    return cached_;
}

template <int D>
Vec<D> EllipticalDropMonaghan1994<D>::velocity(const Vec<D>& x, double t) const {
    const double rate = at(t).rate;
    return Vec<D>(-rate * (x[0] - centre_[0]), rate * (x[1] - centre_[1]));
}

template <int D>
double EllipticalDropMonaghan1994<D>::pressure(const Vec<D>& x, double t, const FlowConstants<D>& constants) const {
    const State s = at(t);
    const double a2 = s.ratio * s.ratio, a4 = a2 * a2;
    const double rateOfRate = s.rate * s.rate * (a4 - 1.0) / (a4 + 1.0);
    const double centre = 0.5 * constants.rho0 * a2 * radius_ * radius_ * (s.rate * s.rate - rateOfRate);
    const Vec<D> r = x - centre_;
    return centre * (1.0 - r[0] * r[0] / (a2 * radius_ * radius_) - r[1] * r[1] * a2 / (radius_ * radius_));
}

template class EllipticalDropMonaghan1994<2>;

}  // namespace sph
