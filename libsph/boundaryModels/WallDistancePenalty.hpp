// The deficiency correction's default repulsion partner: a penalty on the distance to the
// wall particles' tangent planes, blended over the wall particles within the kernel support,
// so that a fluid particle sliding along a wall feels no bumps between wall particles (the
// discrete Lennard-Jones and Monaghan-Kajtar laws with wall spacing dx drag a dam-break front
// measurably: doc/boundaryFindings.md). For fluid particle i, over wall particles j of area A_j:
//   a_i += [zeta (c0/d0) max(0, u_i) sum_j A_j W_ij g_ij^2 n_j + sum_j A_j W_ij H(u_ij) s_ij^2 (K/dx) n_j] / sum_j A_j W_ij
//   u_i = sum_j A_j W_ij g_ij^2 u_ij / sum_j A_j W_ij g_ij^2 (the mean closing speed, weighted by the damper's gaps)
//   g_ij = max(0, 1 - (r_ij . n_j) / d0),   s_ij = max(0, 1 - (r_ij . n_j) / d_s),   d_s <= d0
//   u_ij = -(v_i - v_j) . n_j (the closing speed on wall particle j),   H(u) = 1 for u >= 0, else 0
// or, with `closingSpeed each`, the damper on each wall particle's closing speed:
//   sum_j A_j W_ij g_ij^2 zeta (c0/d0) max(0, u_ij) n_j in place of the first sum
// On a curved wall, fluid sliding past closes on the wall particles ahead of it as fast as it
// leaves those behind; the damper on each one's closing speed takes the first and not the
// second and drags it: a sphere of radius 3 dx oscillating in a tank takes 2.2-2.6 times the
// other models' in-line force with `each`, 1.4-1.7 times with the mean (doc/boundaryFindings.md,
// "Why the damper drags"). The mean is weighted by the damper's own gaps, so that where two
// faces meet it is the nearer one's. Zero beyond d0 (default dx/2, where the first fluid row
// starts), so fluid at rest on the wall feels nothing. The sums run over the wall particles with r_ij . n_j >= 0, unless fluid i
// lies behind its nearest wall particle's plane (it has crossed the wall: then over all):
// beyond a convex edge (behind a box, above a bulge's crest) fluid lies behind the planes of
// the face that ends there, and their gaps, growing with the depth behind them, made a damper
// far past the step's stability (doc/boundaryFindings.md, "Fluid beyond a convex edge").
// The damper zeta stops particles closing on the wall without storing energy. The spring K (a
// squared velocity; default c0^2/200) holds what the correction does not: a slow creep through
// a one-layer floor, which the damper, resisting speed only, lets through. Acting within d_s
// (default d0/2 = dx/4) it leaves the water at rest untouched. It pushes only while the
// particle closes on the wall or rests (H): it gives back no energy an impact stored, so an
// impact does not ring (doc/boundaryFindings.md, "The partner").
// Example (constant/boundaryProperties, inside a deficiency-correction patch):
//   repulsion { type wallDistance; K 11.8; damping 1; distance 0.0075; springDistance 0.00375; closingSpeed mean; }
#pragma once

#include "core/Vector.hpp"

#include <algorithm>

namespace sph {

struct WallDistancePenalty {
    double K;
    double dx;
    double distance;  // d0
    double zeta;      // the damper's coefficient
    double c0;
    double springDistance;  // d_s <= d0: where the spring starts

    bool meanClosingSpeed = true;  // the damper on the mean closing speed (the default), not each wall particle's

    // One fluid particle's sums over its wall particles j (weight A_j W_ij): `each` for
    // `closingSpeed each`, the rest for the mean closing speed (the default).
    template <int D>
    struct Sums {
        Vec<D> each = Vec<D>::Zero(), meanDamper = Vec<D>::Zero(), spring = Vec<D>::Zero();
        double damperWeight = 0.0, damperClosing = 0.0, weight = 0.0;
    };

    // One wall particle's term, times A_j W_ij: rDotN = r_ij . n_j, closingSpeed = -(v_i - v_j) . n_j.
    double term(double rDotN, double closingSpeed) const {
        const double gap = std::max(0.0, 1.0 - rDotN / distance);
        const double springGap = std::max(0.0, 1.0 - rDotN / springDistance);
        const double spring = closingSpeed >= 0.0 ? springGap * springGap * K / dx : 0.0;
        return gap * gap * (zeta * c0 / distance * std::max(0.0, closingSpeed)) + spring;
    }

    // Wall particle j's terms; Mean is meanClosingSpeed, a template argument so that the pair
    // loop neither branches on it nor sums for the damper the case did not select.
    template <bool Mean, int D>
    void add(Sums<D>& sums, double weight, double rDotN, double closingSpeed, const Vec<D>& normal) const {
        sums.weight += weight;
        if constexpr (!Mean) {
            sums.each += (weight * term(rDotN, closingSpeed)) * normal;
        } else {
            const double gap = std::max(0.0, 1.0 - rDotN / distance), damperWeight = weight * gap * gap;
            sums.meanDamper += damperWeight * normal;
            sums.damperWeight += damperWeight;
            sums.damperClosing += damperWeight * closingSpeed;
            const double springGap = std::max(0.0, 1.0 - rDotN / springDistance);
            if (closingSpeed >= 0.0) sums.spring += (weight * springGap * springGap) * normal;
        }
    }

    // The partner's acceleration of the fluid particle (sums.weight > 0).
    template <bool Mean, int D>
    Vec<D> acceleration(const Sums<D>& sums) const {
        if constexpr (!Mean) {
            return sums.each / sums.weight;
        } else {
            const double closingSpeed = sums.damperWeight > 0.0 ? std::max(0.0, sums.damperClosing / sums.damperWeight) : 0.0;
            return (zeta * c0 / distance * closingSpeed * sums.meanDamper + K / dx * sums.spring) / sums.weight;
        }
    }
};

}  // namespace sph
