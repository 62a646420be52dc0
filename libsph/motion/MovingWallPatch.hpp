// Wall particles moved by their patch's motion, and a free body loaded by its patch: what the
// boundary stage asks of motion/, on the particle store alone (no fluid system).
#pragma once

#include "core/ParticleSet.hpp"
#include "motion/PatchMotion.hpp"

#include <cstddef>
#include <vector>

namespace sph {

// Whether the patch's walls [begin, end) were generated along a 2D curve: their surface particles
// (layer 0) in order along it, each within 1.5 spacings of the next at the start. Decided on the
// whole patch, once: a rank of a decomposed run holds pieces of it.
template <int D>
bool surfaceAlongCurve(const ParticleSet<D>& walls, std::size_t begin, std::size_t end);

// Puts the wall particles [begin, end) where the motion has them at t: position, velocity,
// acceleration and normal of each, from its initial position and normal. A deforming patch's
// normals, spacings and areas are then recomputed: from the moved surface's chords where the
// patch lies along a curve (surfaceAlongCurve), else from the motion's area stretch (Nanson's
// formula). Along a curve, the walls held may be pieces of it (a rank's share): a piece's end
// that is no end of the curve takes itself as its missing neighbour, and its values are the
// owner's to send.
template <int D>
void moveWallPatch(ParticleSet<D>& walls, const PatchMotion<D>& motion, std::size_t begin, std::size_t end, double t, bool alongCurve);

// An owned fluid particle's share of a free body's loads: the reaction of what the patch's wall
// forces added to it, -m_i (a_i - a_i^before), and in 2D its torque about the centre of mass.
template <int D>
struct BodyLoadShare {
    std::size_t particle;  // its place on the rank that took it (once gathered from every rank, in the gathered array)
    Vec<D> force;
    double torque;
};

// The shares of the owned fluid particles the patch's wall forces reached, in storage order (the
// others' are zero: leaving them out changes no sum).
template <int D>
std::vector<BodyLoadShare<D>> bodyLoadShares(const PatchMotion<D>& body, const ParticleSet<D>& fluid, const std::vector<Vec<D>>& accelerationBefore);

// A free body takes the sum of the shares, in their order: F = -sum_i m_i (a_i - a_i^before) and,
// in 2D, the torque of those forces.
template <int D>
void loadFreeBody(PatchMotion<D>& body, const std::vector<BodyLoadShare<D>>& shares, const Vec<D>& gravity, double t);

}  // namespace sph
