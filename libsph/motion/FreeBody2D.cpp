#include "motion/FreeBody2D.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

namespace {

Vec<2> rotate(const Vec<2>& v, double angle) {
    return {std::cos(angle) * v.x() - std::sin(angle) * v.y(), std::sin(angle) * v.x() + std::cos(angle) * v.y()};
}

}  // namespace

FreeBody2D::FreeBody2D(const Dictionary& dict)
    : mass_(dict.getPositive("mass")), inertia_(dict.getPositive("momentOfInertia")), initialCentre_(dict.getVector<2>("centreOfMass")) {
    state_.position = initialCentre_;
    state_.velocity = dict.found("velocity") ? dict.getVector<2>("velocity") : Vec<2>::Zero();
    state_.angle = 0.0;
    state_.angularVelocity = dict.getOrDefault("angularVelocity", 0.0);
    start_ = state_;
}

std::string FreeBody2D::describe() const {
    return fmt::format("freeBody: mass {:g}, momentOfInertia {:g}, centreOfMass ({:g}), velocity ({:g}), angularVelocity {:g}", mass_, inertia_,
                       fmt::join(initialCentre_, " "), fmt::join(state_.velocity, " "), state_.angularVelocity);
}

Kinematics<2> FreeBody2D::at(const Vec<2>& x0, const Vec<2>&, double t) const {
    const Vec<2> arm = rotate(x0 - initialCentre_, state_.angle);
    const Vec<2> perpendicular(-arm.y(), arm.x());
    // Linear extrapolation of the accelerations from the last two evaluations.
    Vec<2> a = last_.acceleration;
    double alpha = last_.angularAcceleration;
    if (samples_ >= 2 && last_.t > previous_.t) {
        const double w = (t - last_.t) / (last_.t - previous_.t);
        a += w * (last_.acceleration - previous_.acceleration);
        alpha += w * (last_.angularAcceleration - previous_.angularAcceleration);
    }
    const double omega = state_.angularVelocity;
    return {state_.position + arm, state_.velocity + omega * perpendicular, a + alpha * perpendicular - omega * omega * arm};
}

Vec<2> FreeBody2D::normalAt(const Vec<2>& n0, double) const { return rotate(n0, state_.angle); }

void FreeBody2D::setLoads(const Vec<2>& force, double torque, const Vec<2>& gravity, double t) {
    force_ = force;
    torque_ = torque;
    const Sample current{t, Vec<2>(force / mass_ + gravity), torque / inertia_};
    if (samples_ > 0 && t == last_.t) {
        last_ = current;  // re-evaluated at the same time: replace, do not shift
    } else {
        previous_ = last_;
        last_ = current;
        ++samples_;
    }
}

void FreeBody2D::predict(double halfDt) {
    start_ = state_;
    state_.position += halfDt * state_.velocity;
    state_.velocity += halfDt * last_.acceleration;
    state_.angle += halfDt * state_.angularVelocity;
    state_.angularVelocity += halfDt * last_.angularAcceleration;
}

void FreeBody2D::correct(double dt) {
    state_.velocity = start_.velocity + dt * last_.acceleration;
    state_.position = start_.position + 0.5 * dt * (start_.velocity + state_.velocity);
    state_.angularVelocity = start_.angularVelocity + dt * last_.angularAcceleration;
    state_.angle = start_.angle + 0.5 * dt * (start_.angularVelocity + state_.angularVelocity);
}

}  // namespace sph
