// A free rigid body in 2D (translation and rotation) moved by the fluid: the patch's particles
// follow x = X + R(theta) (x0 - X0). Each evaluation the patch's wall force on the fluid,
// -sum_i m_i delta a_i (delta a_i: what the patch's model added to particle i), and its torque
// about X (taken at the fluid particles, exact for central forces) set
//   A = F/M + g,   alpha = T/I,
// and the body is advanced by the same symplectic predictor-corrector as the fluid. The wall
// particles' acceleration, which the deficiency correction needs before the loads of the
// current evaluation are known, is extrapolated linearly in time from the last two A and alpha
// (the paper's suggestion; it degrades as the body gets lighter than the fluid).
// Only wall-force models (repulsion, deficiency correction) load a free body.
// Example (a patch's motion):
//   motion { type freeBody; mass 12.5; momentOfInertia 0.1; centreOfMass (1 0.5); velocity (0 0); angularVelocity 0; }
#pragma once

#include "motion/PatchMotion.hpp"

namespace sph {

class FreeBody2D : public PatchMotion<2> {
public:
    explicit FreeBody2D(const Dictionary& dict);
    std::string describe() const override;
    bool isFree() const override { return true; }
    Vec<2> centreOfMass() const override { return state_.position; }
    Kinematics<2> at(const Vec<2>& initialPosition, const Vec<2>& initialNormal, double t) const override;
    Vec<2> normalAt(const Vec<2>& initialNormal, double t) const override;
    void setLoads(const Vec<2>& force, double torque, const Vec<2>& gravity, double t) override;
    void predict(double halfDt) override;
    void correct(double dt) override;
    std::vector<double> savedState() const override;
    void restore(const std::vector<double>& saved, const std::string& source) override;

    struct State {
        Vec<2> position, velocity;
        double angle, angularVelocity;
    };
    const State& state() const { return state_; }
    const Vec<2>& force() const { return force_; }
    double torque() const { return torque_; }

private:
    double mass_, inertia_;
    Vec<2> initialCentre_;
    State state_, start_;
    Vec<2> force_ = Vec<2>::Zero();
    double torque_ = 0.0;
    // The last two (time, linear acceleration, angular acceleration), for extrapolation.
    struct Sample {
        double t;
        Vec<2> acceleration;
        double angularAcceleration;
    };
    struct LoadHistory {
        Sample last{0.0, Vec<2>::Zero(), 0.0}, previous{0.0, Vec<2>::Zero(), 0.0};
        int samples = 0;
    };
    LoadHistory loads_;
    // The history as the last evaluation found it: a restart repeats that evaluation from it.
    LoadHistory beforeLastLoads_;
};

}  // namespace sph
