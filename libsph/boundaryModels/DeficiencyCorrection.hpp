// The boundary deficiency correction of Jones, Yang & McCue-Weil (2010): one layer of wall
// particles on the wall surface, out of the fluid's kernel sums; the acceleration that the
// missing virtual particles would give is added back by a coefficient per wall particle,
// blended over the wall particles within reach, so the wall can move and deform with no
// virtual particle to clump. Per evaluation:
//  1. per fluid particle i, over the wall particles j within r_inf (the kernel support):
//       the blend  c_i = sum_j W_ij wn_ij d_ij   and the area integral  g_i = sum_j W_ij A_j n_j
//     with d_ij = n_j (direction normal) or r_ij/|r_ij| (radial), A_j the wall particle's area
//     and wn_ij the weighting: DeficiencyWeightingJones2010 (published, w_ij / sum_k w_ik) or
//     DeficiencyWeightingBoundaryIntegral (A_j; then g_i = c_i for the normal direction);
//  2. per wall particle j, over the fluid s within r_inf:
//       p_j = the wall pressure of Adami et al. (2012) (WallPressureExtrapolation), never below
//             the background pressure p0; rho_j = rho(p_j) by the equation of state;
//       R_j = sum_s W_sj g_s.n_j / sum_s W_sj c_s.n_j, the blend's scale to the area integral
//             (1 for the boundary-integral weighting with normal direction; 0 with no fluid);
//     and the push P_ij on fluid particle i by `calibration`:
//       wallPressure (default): P_ij = (rho_j p_i / rho_i^2 + p_j / rho_j) R_j, the pressure term
//           of virtual particles at p_j, rho_j filling the space behind the wall: by the
//           divergence theorem their kernel-gradient sum is -sum_j W_ij A_j n_j;
//       calibrated (the paper's, its reading of METHOD.md): P_ij = -C_j with
//           C_j = sum_s ((a_s^unc - a_j).n_j) / sum_s (c_s.n_j) over the nearest-k sample
//           (ties at the k-th distance all taken), bounded to [2 C_j^p, 0], C_j^p = -2 p_j R_j / rho_j;
//       literal: the same with sum_s W(|r_sj|) as denominator;
//     calibrated and literal may be smoothed in time, C_j <- (1 - lambda) C_j + lambda C_j^new;
//  3. a_i += sum_j P_ij W_ij wn_ij d_ij; with wallPressure also the virtual particles'
//     pressure gradient along the wall, -(g - a_j) times the kernel's volume behind the wall
//     (KernelOutsideFraction: sum_j A_j Psi(|r_ij|) (r_ij.n_j)/|r_ij|), and with continuity
//     density their compression  drho_i/dt += -sum_j rho_j R_j W_ij wn_ij (v_i - v_j).d_ij
//     (the paper's calibration, which cancels accelerations, blew up a hydrostatic tank with it);
//  4. with laminar viscosity at a no-slip wall (noSlip, the default there), the virtual
//     particles' laminar stress (Morris et al. 1997, the fluid's own term):
//       a_i += sum_j nu (1 + rho_j/rho_i) Phi_ij (v_i - v_j + G_j delta(r_ij.n_j)),
//     Phi_ij = A_j Psi_f(|r_ij|) (r_ij.n_j)/|r_ij| the integral of f(s) = s W'(s)/(s^2 + 0.01 h^2)
//     over the space behind the wall (KernelOutsideFraction with f, summed over 5 sub-elements
//     of a 2D wall particle's segment or 3 x 3 of a 3D one's square): the virtual particles'
//     velocity is the fluid's extrapolated linearly through the wall's, v_j - G_j depth, with
//     G_j = (v^_j - v_j) / max(y^_j, dx/2), v^_j and y^_j the Shepard means of the fluid's
//     velocity and height above the wall around j, and delta the mean depth that f samples
//     behind a flat wall (MeanDepthBehindPlane): exact for a linear shear flow past a flat wall.
//     Without it the walls are free-slip: a Poiseuille flow accelerated as a plug;
//  5. the partner: the wallDistance damper (default, WallDistancePenalty) or a discrete law
//     (Monaghan & Kajtar 2009, Lennard-Jones) adds its force. The damper blends the wall
//     particles whose tangent plane fluid i lies in front of, and all of them where i lies
//     behind its nearest wall particle's plane (it has crossed the wall): fluid beyond a convex
//     edge lies behind the planes of the face that ends there without having crossed it.
// Why wallPressure is the default (doc/boundaryFindings.md): the calibrated C_j makes the
// sampled particles' normal acceleration equal the wall's, so it also cancels the real
// deceleration of fluid arriving at a wall (impacts blow up) and has no bound where the
// sample's kernel sum is far from complete; without the continuity term fluid pressing on a
// wall never compresses; without the gradient along the wall fluid beside a side wall sinks. p_j is bounded by the fluid's pressure and the
// hydrostatic offset over r_inf whatever the sample, and C_j^p = -2 p/rho reproduces the paper's uniform-pressure calibration with the
// boundary-integral weighting. The walls' pressure and density fields hold p_j and rho_j (ParaView, wall sensors), and correctionCoefficient the
// uniform-pressure coefficient C_j (-2 p_j R_j / rho_j with wallPressure). Reference: V. Jones, Q. Yang, L. McCue-Weil, Ship Science & Technology
// 4(7) (2010) 21-30, Eqs. (7), (8); S. Adami, X.Y. Hu, N.A. Adams, J. Comput. Phys. 231 (2012) 7057, Eq. (27); the boundary integral as in
// Kulasegaram et al. (2004) and Ferrand et al. (2013). Example (constant/boundaryProperties):
//   tank
//   {
//       type              deficiencyCorrection;     // or deficiencyCorrectionBoundaryIntegral
//       repulsion         { type wallDistance; K 0; damping 1; }   // or monaghanKajtar, lennardJones
//       calibration       wallPressure;             // or calibrated, literal
//       direction         normal;                   // or radial
//       // calibrated and literal only:
//       sample            { type nearest; size 4; } // or { type withinRadius; radius 0.02; }
//       temporalSmoothing 1;                        // lambda in (0, 1]; 1: none
//       noSlip            yes;   // with viscosity laminar (the default there); free slip otherwise
//   }
#pragma once

#include "boundaryModels/BoundaryModel.hpp"
#include "boundaryModels/RepulsiveWall.hpp"
#include "boundaryModels/WallDistancePenalty.hpp"
#include "kernels/KernelOutsideFraction.hpp"
#include "kernels/MeanDepthBehindPlane.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

namespace sph {

enum class DeficiencyCalibration { WallPressure, Calibrated, Literal };

template <int D, class Weighting>
class DeficiencyCorrection : public BoundaryModel<D> {
public:
    DeficiencyCorrection(const Dictionary& dict, const ModelContext& context, std::string typeName);

    bool actsThroughWallParticles() const override { return false; }
    bool setsWallPressure() const override { return true; }  // p_j, extrapolated for the virtual particles
    bool needsUncorrectedAcceleration() const override { return calibration_ != DeficiencyCalibration::WallPressure; }
    bool addsViscousStress() const override { return noSlip_; }
    std::string describe() const override;
    // Fluid i reads the push of walls j within r_inf, whose R_j (and sample) reads the fluid s
    // within r_inf (the sample radius), whose blends read the walls within r_inf of s.
    double reach(double support) const override { return 2.0 * support + std::max(support, sampleRadius_); }
    void addFields(const BoundaryView<D>& view) override;
    void resume(const BoundaryView<D>& view, std::size_t begin, std::size_t end) override;
    void addWallForces(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, std::size_t begin, std::size_t end) override;

private:
    // The three passes of an evaluation: the fluid particles' weights and blends, the wall
    // particles' pressures and pushes (and velocity gradients G_j with noSlip), the correction
    // applied to the fluid; with noSlip a fourth adds the laminar stress.
    template <bool Radial, class Kernel>
    void weighPairs(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, const Kernel& kernel);
    template <bool WallPressure, bool NoSlip, class Kernel>
    void setWallParticles(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, const Vec<D>& gravity, double lambda,
                          const Kernel& kernel);
    template <bool Radial, bool WallPressure, bool DistancePartner, bool MeanClosingSpeed>
    void applyCorrection(const BoundaryView<D>& view, const Vec<D>& gravity);
    // The virtual particles' laminar stress at a no-slip wall, over the pairs pass 1 kept.
    void applyNoSlip(const BoundaryView<D>& view);
    // The area integral g_i is the blend c_i itself unless the weights or directions differ from A_j n_j.
    static constexpr bool separateAreaIntegral(bool radial) { return Weighting::normalised || radial; }
    // The direction of a pair's correction: the wall normal n_j, or radial (x_i - x_j) / r_ij.
    template <bool Radial>
    static Vec<D> direction(const Vec<D>& normal, const Vec<D>& r, double distance) {
        if constexpr (Radial)
            return r / distance;
        else
            return normal;
    }

    std::string typeName_;
    WallDistancePenalty penalty_;            // the partner unless a discrete law is named
    std::optional<RepulsionLaw> repulsion_;  // a discrete law (Monaghan-Kajtar, Lennard-Jones)
    DeficiencyCalibration calibration_;
    bool radialDirection_;
    int sampleSize_;       // nearest-k sample; 0 when sampling by radius
    double sampleRadius_;  // radius of the sample (the kernel support for nearest-k)
    double smoothing_;
    bool noSlip_;
    double nu_;               // the laminar viscosity's, with noSlip
    double smoothingLength_;  // h, for the laminar term's 0.01 h^2
    double spacing_;          // dx, the least height y^_j
    bool firstEvaluation_ = true;
    bool repeatWrittenCoefficients_ = false;  // restart: the written C_j already hold this evaluation's
    // A fluid-wall pair within the support, found once per evaluation (pass 1) and read again
    // by the correction (pass 3).
    struct WallPair {
        std::uint32_t wall;
        double kernel;       // W_ij
        double blendWeight;  // W_ij w_ij
        double distance;
        Vec<D> r;  // x_i - x_j, nearest image
    };
    struct PairRange {
        std::uint32_t thread, begin, end;  // fluid particle i's pairs in that thread's list
    };
    // This evaluation only; kept between evaluations so that no step allocates once sizes settle.
    std::vector<std::vector<WallPair>> pairsPerThread_;
    std::vector<PairRange> pairRanges_;  // per fluid particle
    std::vector<double> weightSum_;      // per fluid particle: sum_j w_ij
    std::vector<Vec<D>> blend_;          // c_i
    std::vector<Vec<D>> areaIntegral_;   // g_i, where it differs from c_i
    KernelOutsideFraction<D> outsideFraction_;
    std::vector<double> push_;                        // per wall particle: p_j R_j / rho_j, or -C_j
    std::vector<double> virtualDensity_;              // per wall particle: rho_j R_j
    KernelOutsideFraction<D> viscousFlux_;            // Phi_ij, with noSlip
    MeanDepthBehindPlane<D> viscousDepth_;            // delta, with noSlip
    std::vector<Vec<D>> wallShear_;                   // per wall particle: G_j, with noSlip
    std::vector<std::array<Vec<D>, 2>> elementAxes_;  // per wall particle: its sub-elements' steps, with noSlip
};

}  // namespace sph
