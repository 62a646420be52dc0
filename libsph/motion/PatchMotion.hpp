// Prescribed motion of a wall patch, selected in the patch's entry of
// constant/boundaryProperties:
//   piston { type dummyParticles; motion { type oscillation; amplitude (0.05 0); frequency 1; } }
// Every particle follows the motion of the material point where it started: position,
// velocity and acceleration at time t. Rigid motions turn the normals with the patch; a
// deformation moves particles by a displacement field, and the wall-force models' normals,
// spacings and areas are then recomputed (motion/MovingWallPatch: from the moved surface's
// chords on a 2D curve, else from the motion's areaStretch).
#pragma once

#include "core/Registry.hpp"
#include "core/Vector.hpp"
#include "io/Dictionary.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sph {

template <int D>
struct Kinematics {
    Vec<D> position, velocity, acceleration;
};

template <int D>
class PatchMotion {
public:
    virtual ~PatchMotion() = default;
    virtual std::string describe() const = 0;
    // True when the patch changes shape (normals and spacings must be recomputed).
    virtual bool deforms() const { return false; }
    virtual Kinematics<D> at(const Vec<D>& initialPosition, const Vec<D>& initialNormal, double t) const = 0;
    // The normal at t of a particle whose normal was n0 (rigid motions).
    virtual Vec<D> normalAt(const Vec<D>& initialNormal, double /*t*/) const { return initialNormal; }
    // A deformation's area vector at t per unit initial area, J F^-T n0 (Nanson's formula, F the
    // gradient of the motion at x0): along the new normal, its length the stretch da/dA. Deforming
    // patches whose particles have no order along the surface to take chords along (3D, 2D
    // boxWalls) take their normals and areas from it.
    virtual Vec<D> areaStretch(const Vec<D>& /*initialPosition*/, const Vec<D>& initialNormal, double t) const { return normalAt(initialNormal, t); }
    // FatalError when the motion is not defined over [startTime, endTime] (a table too short).
    virtual void checkCovers(double /*startTime*/, double /*endTime*/) const {}

    // A free body's motion is integrated with the fluid from the loads the fluid exerts; a
    // prescribed motion ignores these.
    virtual bool isFree() const { return false; }
    // A free body's centre of mass now (the point its torque is taken about).
    virtual Vec<D> centreOfMass() const { return Vec<D>::Zero(); }
    virtual void setLoads(const Vec<D>& /*force*/, double /*torque*/, const Vec<D>& /*gravity*/, double /*t*/) {}
    virtual void predict(double /*halfDt*/) {}
    virtual void correct(double /*dt*/) {}

    // Restart: a free body's integrated state, written with each state and restored before the
    // first step of a restarted run (prescribed motions depend on time alone and keep none).
    virtual std::vector<double> savedState() const { return {}; }
    // `source` names the file for the message when `saved` is not a state of this motion.
    virtual void restore(const std::vector<double>& /*saved*/, const std::string& /*source*/) {}
};

// Factory argument: the `motion` dictionary and the case directory (for tables).
template <int D>
using PatchMotionRegistry = Registry<std::unique_ptr<PatchMotion<D>>, const Dictionary&, const std::string&>;

template <int D>
PatchMotionRegistry<D> makePatchMotionRegistry();

}  // namespace sph
