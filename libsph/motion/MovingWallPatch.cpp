#include "motion/MovingWallPatch.hpp"

#include <algorithm>
#include <cmath>

namespace sph {

namespace {

// The surface particles (layer 0) of walls [begin, end), in storage order.
template <int D>
std::vector<std::size_t> surfaceParticles(const ParticleSet<D>& walls, std::size_t begin, std::size_t end) {
    const auto& layer = walls[fields::layer];
    std::vector<std::size_t> surface;
    for (std::size_t w = begin; w < end; ++w)
        if (layer[w] == 0) surface.push_back(w);
    return surface;
}

// Whether surface particles a and b were neighbours along the curve at the start (by the
// spacing at the start, where the state keeps it: the current one stretches with the wall).
bool adjacentAtStart(const ParticleSet<2>& walls, std::size_t a, std::size_t b) {
    const auto& x0 = walls[fields::initialPosition];
    const auto& spacing = walls[walls.has(fields::initialSpacing) ? fields::initialSpacing : fields::spacing];
    return (x0[b] - x0[a]).norm() <= 1.5 * spacing[a];
}

// 2D walls generated along a curve (polyline, polygon, circle, ellipse) keep their surface
// particles in order along it: the normal is the neighbours' chord turned by 90 degrees to the
// side of the initial normal, the spacing the mean distance to the neighbours; a closed curve
// wraps around. Exact for any deformation of a curved wall.
void surfaceFromChords(ParticleSet<2>& walls, std::size_t begin, std::size_t end) {
    auto& normal = walls[fields::normal];
    auto& spacing = walls[fields::spacing];
    auto& area = walls[fields::area];
    const auto& n0 = walls[fields::initialNormal];
    const std::vector<std::size_t> surface = surfaceParticles(walls, begin, end);
    const std::size_t m = surface.size();
    if (m < 3) return;
    const auto& x = walls.position;
    const bool closed = (x[surface.front()] - x[surface.back()]).norm() < 1.5 * spacing[surface.front()];
    for (std::size_t k = 0; k < m; ++k) {
        // A piece's end (a gap to the next particle held) counts as an end of the curve.
        const bool first = k == 0 || !adjacentAtStart(walls, surface[k - 1], surface[k]);
        const bool last = k + 1 == m || !adjacentAtStart(walls, surface[k], surface[k + 1]);
        const std::size_t previous = first ? (k == 0 && closed ? surface[m - 1] : surface[k]) : surface[k - 1];
        const std::size_t next = last ? (k + 1 == m && closed ? surface[0] : surface[k]) : surface[k + 1];
        const Vec<2> chord = x[next] - x[previous];
        Vec<2> n(-chord.y(), chord.x());
        n.normalize();
        if (n.dot(n0[surface[k]]) < 0.0) n = -n;
        normal[surface[k]] = n;
        const double back = (x[surface[k]] - x[previous]).norm(), ahead = (x[next] - x[surface[k]]).norm();
        const bool atEnd = previous == surface[k] || next == surface[k];
        spacing[surface[k]] = atEnd ? std::max(back, ahead) : 0.5 * (back + ahead);
        // The area vector is half the chord turned by 90 degrees: s/sqrt(2) at a right-angled corner.
        area[surface[k]] = atEnd ? spacing[surface[k]] : 0.5 * chord.norm();
    }
}

// Nanson's formula from the motion itself, for every layer (3D surface particles, and 2D
// boxWalls, have no order along the wall): area A0 |J F^-T n0|, the spacing stretched by the
// same ratio to the power 1/(D-1).
template <int D>
void surfaceFromMotion(ParticleSet<D>& walls, const PatchMotion<D>& motion, std::size_t begin, std::size_t end, double t) {
    if (!walls.has(fields::initialArea)) return;  // walls without spacings or areas: normals only matter
    const auto& x0 = walls[fields::initialPosition];
    const auto& n0 = walls[fields::initialNormal];
    const auto& area0 = walls[fields::initialArea];
    const auto& spacing0 = walls[fields::initialSpacing];
    auto& normal = walls[fields::normal];
    auto& spacing = walls[fields::spacing];
    auto& area = walls[fields::area];
    for (std::size_t w = begin; w < end; ++w) {
        const Vec<D> stretched = motion.areaStretch(x0[w], n0[w], t);
        const double ratio = stretched.norm();
        normal[w] = stretched / ratio;
        area[w] = area0[w] * ratio;
        spacing[w] = spacing0[w] * (D == 3 ? std::sqrt(ratio) : ratio);
    }
}

}  // namespace

template <int D>
bool surfaceAlongCurve(const ParticleSet<D>& walls, std::size_t begin, std::size_t end) {
    if constexpr (D != 2) {
        return false;
    } else {
        if (!walls.has(fields::layer) || !walls.has(fields::spacing) || !walls.has(fields::initialPosition)) return false;
        const std::vector<std::size_t> surface = surfaceParticles(walls, begin, end);
        for (std::size_t k = 1; k < surface.size(); ++k)
            if (!adjacentAtStart(walls, surface[k - 1], surface[k])) return false;
        return true;
    }
}

template <int D>
void moveWallPatch(ParticleSet<D>& walls, const PatchMotion<D>& motion, std::size_t begin, std::size_t end, double t, bool alongCurve) {
    const auto& x0 = walls[fields::initialPosition];
    const auto& n0 = walls[fields::initialNormal];
    auto& velocity = walls[fields::velocity];
    auto& acceleration = walls[fields::acceleration];
    auto& normal = walls[fields::normal];
    for (std::size_t w = begin; w < end; ++w) {
        const Kinematics<D> k = motion.at(x0[w], n0[w], t);
        walls.position[w] = k.position;
        velocity[w] = k.velocity;
        acceleration[w] = k.acceleration;
        normal[w] = motion.normalAt(n0[w], t);
    }
    if (!motion.deforms()) return;
    if constexpr (D == 2)
        if (alongCurve) return surfaceFromChords(walls, begin, end);
    if constexpr (D >= 2) surfaceFromMotion(walls, motion, begin, end, t);
}

template <int D>
std::vector<BodyLoadShare<D>> bodyLoadShares(const PatchMotion<D>& body, const ParticleSet<D>& fluid, const std::vector<Vec<D>>& accelerationBefore) {
    const auto& acceleration = fluid[fields::acceleration];
    const double* m = fluid[fields::mass].data();
    const Vec<D> centreOfMass = body.centreOfMass();
    std::vector<BodyLoadShare<D>> shares;
    for (std::size_t i = 0; i < fluid.ownedCount(); ++i) {
        const Vec<D> f = -m[i] * (acceleration[i] - accelerationBefore[i]);
        if (f == Vec<D>::Zero()) continue;
        double torque = 0.0;
        if constexpr (D == 2) torque = (fluid.position[i] - centreOfMass).x() * f.y() - (fluid.position[i] - centreOfMass).y() * f.x();
        shares.push_back({i, f, torque});
    }
    return shares;
}

template <int D>
void loadFreeBody(PatchMotion<D>& body, const std::vector<BodyLoadShare<D>>& shares, const Vec<D>& gravity, double t) {
    Vec<D> force = Vec<D>::Zero();
    double torque = 0.0;
    for (const BodyLoadShare<D>& share : shares) {
        force += share.force;
        torque += share.torque;
    }
    body.setLoads(force, torque, gravity, t);
}

template bool surfaceAlongCurve<1>(const ParticleSet<1>&, std::size_t, std::size_t);
template bool surfaceAlongCurve<2>(const ParticleSet<2>&, std::size_t, std::size_t);
template bool surfaceAlongCurve<3>(const ParticleSet<3>&, std::size_t, std::size_t);
template void moveWallPatch<1>(ParticleSet<1>&, const PatchMotion<1>&, std::size_t, std::size_t, double, bool);
template void moveWallPatch<2>(ParticleSet<2>&, const PatchMotion<2>&, std::size_t, std::size_t, double, bool);
template void moveWallPatch<3>(ParticleSet<3>&, const PatchMotion<3>&, std::size_t, std::size_t, double, bool);
#define SPHKIT_INSTANTIATE(D)                                                                                                           \
    template std::vector<BodyLoadShare<D>> bodyLoadShares<D>(const PatchMotion<D>&, const ParticleSet<D>&, const std::vector<Vec<D>>&); \
    template void loadFreeBody<D>(PatchMotion<D>&, const std::vector<BodyLoadShare<D>>&, const Vec<D>&, double);
SPHKIT_INSTANTIATE(1)
SPHKIT_INSTANTIATE(2)
SPHKIT_INSTANTIATE(3)
#undef SPHKIT_INSTANTIATE

}  // namespace sph
