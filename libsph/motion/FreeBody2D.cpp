#include "motion/FreeBody2D.hpp"

#include "core/FatalError.hpp"

#include <fmt/format.h>

#include <algorithm>
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
    const Sample& last = loads_.last;
    const Sample& previous = loads_.previous;
    Vec<2> a = last.acceleration;
    double alpha = last.angularAcceleration;
    if (loads_.samples >= 2 && last.t > previous.t) {
        const double w = (t - last.t) / (last.t - previous.t);
        a += w * (last.acceleration - previous.acceleration);
        alpha += w * (last.angularAcceleration - previous.angularAcceleration);
    }
    const double omega = state_.angularVelocity;
    return {state_.position + arm, state_.velocity + omega * perpendicular, a + alpha * perpendicular - omega * omega * arm};
}

Vec<2> FreeBody2D::normalAt(const Vec<2>& n0, double) const { return rotate(n0, state_.angle); }

void FreeBody2D::setLoads(const Vec<2>& force, double torque, const Vec<2>& gravity, double t) {
    force_ = force;
    torque_ = torque;
    beforeLastLoads_ = loads_;
    const Sample current{t, Vec<2>(force / mass_ + gravity), torque / inertia_};
    if (loads_.samples > 0 && t == loads_.last.t) {
        loads_.last = current;  // re-evaluated at the same time: replace, do not shift
    } else {
        loads_.previous = loads_.last;
        loads_.last = current;
        ++loads_.samples;
    }
}

void FreeBody2D::predict(double halfDt) {
    start_ = state_;
    state_.position += halfDt * state_.velocity;
    state_.velocity += halfDt * loads_.last.acceleration;
    state_.angle += halfDt * state_.angularVelocity;
    state_.angularVelocity += halfDt * loads_.last.angularAcceleration;
}

void FreeBody2D::correct(double dt) {
    state_.velocity = start_.velocity + dt * loads_.last.acceleration;
    state_.position = start_.position + 0.5 * dt * (start_.velocity + state_.velocity);
    state_.angularVelocity = start_.angularVelocity + dt * loads_.last.angularAcceleration;
    state_.angle = start_.angle + 0.5 * dt * (start_.angularVelocity + state_.angularVelocity);
}

// Saved: the state and the load history before the last evaluation, which the restarted run
// repeats (the loads then come out as they did).
std::vector<double> FreeBody2D::savedState() const {
    const LoadHistory& h = beforeLastLoads_;
    return {state_.position.x(),
            state_.position.y(),
            state_.velocity.x(),
            state_.velocity.y(),
            state_.angle,
            state_.angularVelocity,
            h.last.t,
            h.last.acceleration.x(),
            h.last.acceleration.y(),
            h.last.angularAcceleration,
            h.previous.t,
            h.previous.acceleration.x(),
            h.previous.acceleration.y(),
            h.previous.angularAcceleration,
            static_cast<double>(h.samples)};
}

void FreeBody2D::restore(const std::vector<double>& saved, const std::string& source) {
    if (saved.size() != savedState().size() || !std::all_of(saved.begin(), saved.end(), [](double v) { return std::isfinite(v); }))
        throw FatalError(fmt::format("error: '{}': the saved free-body state has {} values, expected {} finite values (a corrupt state file?)",
                                     source, saved.size(), savedState().size()));
    state_ = {{saved[0], saved[1]}, {saved[2], saved[3]}, saved[4], saved[5]};
    start_ = state_;
    loads_.last = {saved[6], {saved[7], saved[8]}, saved[9]};
    loads_.previous = {saved[10], {saved[11], saved[12]}, saved[13]};
    loads_.samples = static_cast<int>(saved[14]);
    beforeLastLoads_ = loads_;
}

}  // namespace sph
