// The boundary deficiency correction of Jones, Yang & McCue-Weil (2010), with a repulsion
// partner (Monaghan & Kajtar 2009 or Lennard-Jones) to stop penetration. Per evaluation:
//  1. a_i^unc: the fluid acceleration of the force loop, without any wall force;
//  2. per wall particle j, from a sample S_j of fluid particles near it:
//       calibrated (default): C_j = sum_s ((a_s^unc - a_j) . n_j) / sum_s (c_s . n_j),
//                             c_s = sum_{k in Omega'_s} W(|r_sk|) wn_sk d_sk
//       literal:              C_j = sum_s ((a_s^unc - a_j) . n_j) / sum_s W(|r_sj|)
//     The paper averages the ratios; the ratio of the sums is the same for one sample (1D) or
//     equal denominators (a straight wall), and does not divide by the near-zero c_s . n_j
//     of a sample whose blend is dominated by another face (the corner of a hydrostatic tank
//     blew up with the mean of ratios);
//     optionally smoothed in time, C_j <- (1 - lambda) C_j + lambda C_j^new;
//  3. a_i += -sum_{j in Omega'_i} C_j W(|r_ij|) wn_ij d_ij over wall particles within r_inf
//     (the kernel support), d_ij = n_j (direction normal) or r_ij/|r_ij| (radial), wn_ij the
//     weighting: DeficiencyWeightingJones2010 (published, w_ij normalised over Omega'_i) or
//     DeficiencyWeightingBoundaryIntegral (area vectors, unnormalised);
//  4. the repulsion partner adds its force.
// a_j is the wall's acceleration (zero for fixed walls). A deficiency pulls the fluid towards
// the wall, so C_j < 0 and the correction points along +n_j.
// Reference: V. Jones, Q. Yang, L. McCue-Weil, Ship Science & Technology 4(7) (2010) 21-30,
// Eqs. (7), (8); doc/models.md restates them.
// Example (constant/boundaryProperties):
//   tank
//   {
//       type              deficiencyCorrection;     // or deficiencyCorrectionBoundaryIntegral
//       repulsion         { type monaghanKajtar; K 10; }
//       calibration       calibrated;               // or literal
//       direction         normal;                   // or radial
//       sample            { type nearest; size 4; } // or { type withinRadius; radius 0.02; }
//       temporalSmoothing 1;                        // lambda in (0, 1]; 1: none
//   }
#pragma once

#include "boundaryModels/BoundaryModel.hpp"
#include "boundaryModels/RepulsiveWall.hpp"

#include <vector>

namespace sph {

template <int D, class Weighting>
class DeficiencyCorrection : public BoundaryModel<D> {
public:
    DeficiencyCorrection(const Dictionary& dict, const ModelContext& context, std::string typeName);

    bool actsThroughWallParticles() const override { return false; }
    bool needsUncorrectedAcceleration() const override { return true; }
    std::string describe() const override;
    void addFields(FluidSystem<D>& system) override;
    void resume(const FluidSystem<D>& system, std::size_t begin, std::size_t end) override;
    void addWallForces(FluidSystem<D>& system, const CellLinkedList<D>& patchCells, std::size_t begin, std::size_t end, double t) override;

private:
    std::string typeName_;
    RepulsionLaw repulsion_;
    bool literal_;
    bool radialDirection_;
    int sampleSize_;       // nearest-k sample; 0 when sampling by radius
    double sampleRadius_;  // radius of the sample (the kernel support for nearest-k)
    double smoothing_;
    bool firstEvaluation_ = true;
    bool repeatWrittenCoefficients_ = false;  // restart: the written C_j already hold this evaluation's
    std::vector<double> weightSum_;  // per fluid particle, this evaluation only
    std::vector<Vec<D>> blend_;      // c_i, per fluid particle
};

}  // namespace sph
