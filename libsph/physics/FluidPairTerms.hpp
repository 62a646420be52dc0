// What one pair of fluid particles k, l adds to the rates, with r = x_k - x_l, v_kl = v_k - v_l
// and F = W'(|r|)/|r| (grad_k W_kl = F r):
//   dv_k/dt += m_l a_kl,   dv_l/dt -= m_k a_kl,   a_kl = alongR r + alongV v_kl
//     alongR = -(p_k/rho_k^2 + p_l/rho_l^2) F            (pressure)
//              + Pi_kl                                   (a viscosity along r: Monaghan 1992)
//     alongV = a viscosity along v_kl                    (Morris 1997)
//   drho_k/dt += m_l F v_kl.r + D_kl V_l,   drho_l/dt += m_k F v_kl.r + D_lk V_k
//     (continuity; D: the density diffusion, V = m/rho)
// Plain numbers in and out, so that the pair loop (FluidRates.tpp) runs it in vector lanes; which
// terms exist is fixed at compile time (FluidRateTerms): a term the case did not select is not
// evaluated. doc/models.md has each term with its reference.
#pragma once

#include "core/Vector.hpp"
#include "densityDiffusion/Antuono2010.hpp"
#include "physics/FluidWallPair.hpp"

#include <array>
#include <cstddef>

namespace sph {

// The terms one instantiation of the rates evaluates: all of them, or one side of an IMEX split
// (ViscousOnly: the implicit part; the explicit part is the instantiation without viscosity).
template <bool Continuity, bool ViscousOnly, class Viscosity, class Diffusion>
struct FluidRateTerms {
    static constexpr bool pressure = !ViscousOnly;
    static constexpr bool continuity = Continuity;  // the density is evolved (else summed)
    static constexpr bool densityRate = Continuity && !ViscousOnly;
    static constexpr bool diffuses = densityRate && Diffusion::enabled;
    static constexpr bool densityGradient = diffuses && usesDensityGradient<Diffusion>;
    static constexpr bool readsVelocity = densityRate || Viscosity::enabled;
    static constexpr bool readsDensity = Viscosity::enabled || diffuses;
    static constexpr bool alongVelocity = actsAlongVelocity<Viscosity>;
};

// The per-particle inputs of the pair terms, in the fluid cell list's order; an array the
// instantiated terms do not read is not set.
template <int D>
struct PairInputs {
    const double* mass = nullptr;
    const double* pressureOverDensity2 = nullptr;
    const double* density = nullptr;
    const double* volume = nullptr;
    const double* densityGradient = nullptr;  // D doubles per particle
};

// Particle k's inputs, read once for all its pairs.
template <int D>
struct PairParticle {
    double mass = 0.0, pressureOverDensity2 = 0.0, density = 0.0, volume = 0.0;
    std::array<double, D> densityGradient{};
};

template <int D, class Terms, class Viscosity, class Diffusion>
struct FluidPairTerms {
    Viscosity viscosity;
    Diffusion diffusion;
    Vec<D> gravity;  // Fourtakas' hydrostatic part
    PairInputs<D> in;

    PairParticle<D> particle(std::size_t k) const {
        PairParticle<D> p;
        p.mass = in.mass[k];
        if constexpr (Terms::pressure) p.pressureOverDensity2 = in.pressureOverDensity2[k];
        if constexpr (Terms::readsDensity) p.density = in.density[k];
        if constexpr (Terms::diffuses) p.volume = in.volume[k];
        if constexpr (Terms::densityGradient)
            for (int d = 0; d < D; ++d) p.densityGradient[d] = in.densityGradient[k * D + d];
        return p;
    }

    // a_kl = alongR r + alongV v_kl, from v_kl.r, r^2 and 1/(r^2 + eta^2).
    void acceleration(const PairParticle<D>& k, std::size_t l, double F, double r2, double inverseRegularisedR2, double vDotR, double& alongR,
                      double& alongV) const {
        alongR = 0.0;
        alongV = 0.0;
        if constexpr (Terms::pressure) alongR -= (k.pressureOverDensity2 + in.pressureOverDensity2[l]) * F;
        if constexpr (Viscosity::enabled) {
            const double factor = viscosity.pairFactor(vDotR, r2, inverseRegularisedR2, k.density, in.density[l], F);
            if constexpr (Viscosity::alongSeparation)
                alongR += factor;
            else
                alongV += factor;
        }
    }

    // The density rates the pair adds to k and to l.
    void densityRates(const PairParticle<D>& k, std::size_t l, const double (&r)[D], double F, double r2, double inverseRegularisedR2, double vDotR,
                      double& toK, double& toL) const {
        const double divergencePerMass = F * vDotR;
        toK = in.mass[l] * divergencePerMass;
        toL = k.mass * divergencePerMass;
        if constexpr (Terms::diffuses) {
            double diffusionToK = 0.0, diffusionToL = 0.0;
            if constexpr (Terms::densityGradient) {
                double gradientSumDotR = 0.0;
                for (int d = 0; d < D; ++d) gradientSumDotR += (k.densityGradient[d] + in.densityGradient[l * D + d]) * r[d];
                diffusion.pairRates(r2, inverseRegularisedR2, k.density, in.density[l], F, gradientSumDotR, diffusionToK, diffusionToL);
            } else {
                double gravityDotR = 0.0;
                for (int d = 0; d < D; ++d) gravityDotR += gravity[d] * r[d];
                diffusion.pairRates(gravityDotR, r2, inverseRegularisedR2, k.density, in.density[l], F, diffusionToK, diffusionToL);
            }
            toK += diffusionToK * in.volume[l];
            toL += diffusionToL * k.volume;
        }
    }
};

}  // namespace sph
