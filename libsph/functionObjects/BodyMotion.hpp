// bodyMotion: the state and loads of a free body (a patch whose motion is freeBody) over time:
// postProcessing/<name>/<t0>/body.dat with columns t, X, Y, angle, Vx, Vy, omega, Fx, Fy, torque
// (F and torque: the fluid's force on the body, gravity excluded).
// Example (system/controlDict, functions):
//   cylinder { type bodyMotion; patch cylinder; executeInterval 0.01; }
#pragma once

#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/TimeSeriesFile.hpp"

namespace sph {

template <int D>
class BodyMotion : public FunctionObject<D> {
public:
    BodyMotion(const Dictionary& dict, const FunctionObjectContext<D>& context);
    std::string describe() const override { return "bodyMotion: patch " + patch_; }
    void execute(const FluidSystemView<D>& system, double t) override;

private:
    std::string patch_;
    const Dictionary* dict_;
    TimeSeriesFile out_;
};

}  // namespace sph
