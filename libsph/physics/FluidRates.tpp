// The loop driver of the fluid's rates: threads, cell order, vector lanes and accumulators,
// calling the pair physics of FluidPairTerms.hpp and FluidWallPair.hpp. Included by
// FluidSystem.tpp; one instantiation per kernel x viscosity x diffusion x terms.
//
// Fluid-fluid pairs are evaluated once each, in cell order: the inputs a pair reads are copied
// into that order, each thread takes one contiguous block of it (the same for a given thread
// count, so a run is reproducible; the blocks of the cell list's placing and of the copies, so a
// thread reads mostly what it wrote itself: doc/performance.md, "One block per thread"), and a
// thread adds to both particles of a pair in its own accumulator; a second pass sums the
// accumulators, adds gravity and the fluid-wall terms, and writes the rates in storage order.
// Summation order depends on the thread count (rates agree to round-off, not bit for bit). In a
// step's last evaluation with particle shifting, each particle's pair loop is followed by the
// shifting pass's sums over the same list (ShiftingPairSums.hpp): a branch per particle, not per
// pair; in 2D they read the distances and gradient factors the pair loop stored. With delta-SPH
// the pass reads the moment and density differences from its gradient sums.
#include "physics/FluidPairTerms.hpp"
#include "physics/ShiftingPairSums.hpp"

#include <Eigen/LU>  // delta-SPH's renormalisation matrix

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <omp.h>
#include <type_traits>
#include <vector>

namespace sph {
namespace {

template <int D, class Terms, class Kernel, class Viscosity, class Diffusion>
class FluidRatesLoop {
public:
    using Stencil = typename CellLinkedList<D>::StencilRanges;
    // Pairs in vector lanes (AVX2: four doubles) where a particle has many: 87 pairs in the 3D
    // benchmark. With 12 (2D), the loop over them in lanes, its padding and the separate scatter
    // cost more than one fused scalar loop, which 2D keeps (doc/performance.md, "Pairs in vector
    // lanes (3D)").
    static constexpr std::size_t lanes = D == 3 ? 4 : 1;
    // What delta-SPH's gradient sums per particle: the moment matrix, then the density differences.
    using Moment = Eigen::Matrix<double, D, D>;
    static constexpr int gradientSumCount = D * D + D;

    // Sizes the cell-ordered copies and accumulators; call before the parallel region. With
    // shiftingSums, the loop also takes the shifting pass's pair sums into it.
    FluidRatesLoop(FluidSystem<D>& s, CellOrderedFluid<D>& ordered, ParticleShiftingScratch<D>* shiftingSums, Kernel kernel, Viscosity viscosity,
                   Diffusion diffusion, const Vec<D>& gravity)
        : cells_(s.fluidCells()),
          wallCells_(s.wallCells()),
          ordered_(ordered),
          shifting_(shiftingSums),
          kernel_(kernel),
          pair_{viscosity, diffusion, gravity, {}} {
        n_ = cells_.pointCount();
        owned_ = s.fluid.ownedCount();
        x_ = s.fluid.position.data();
        v_ = s.fluid[fields::velocity].data();
        m_ = s.fluid[fields::mass].data();
        rho_ = s.fluid[fields::density].data();
        p_ = s.fluid[fields::pressure].data();
        a_ = s.fluid[fields::acceleration].data();
        drho_ = Terms::continuity ? s.fluid[fields::densityRate].data() : nullptr;
        bodyForce_ = Terms::pressure ? gravity : Vec<D>::Zero();
        wallVelocity_ = s.walls[fields::velocity].data();
        wall_ = {s.walls[fields::mass].data(), s.walls[fields::pressure].data(), s.walls[fields::density].data(),
                 Viscosity::enabled ? s.walls[fields::viscousVelocity].data() : nullptr};
        radius_ = s.supportRadius();
        eta2_ = viscousRegularisation(s.smoothingLength());
        const auto threads = static_cast<std::size_t>(omp_get_max_threads());
        ordered.mass.resize(n_);
        if constexpr (Terms::pressure) ordered.pressureOverDensity2.resize(n_);
        if constexpr (Terms::readsVelocity) ordered.velocity.resize(n_);
        if constexpr (Terms::readsDensity) ordered.density.resize(n_);
        if constexpr (Terms::diffuses) ordered.volume.resize(n_);
        if constexpr (Terms::densityGradient) {
            ordered.densityGradient.resize(n_);
            ordered.gradientSums.resize(threads);
            ordered.neighbourLists.resize(threads);
        }
        ordered.acceleration.resize(threads);
        if constexpr (Terms::densityRate) ordered.densityRate.resize(threads);
        if (shifting_) {
            shifting_->volume.resize(n_);
            shifting_->density.resize(n_);
            shifting_->sumsOfThread.resize(threads);
            shifting_->momentSumsOfThread = Terms::densityGradient ? &ordered.gradientSums : nullptr;
        }
        // A copy's shifting sums are read (its free-surface normal reaches the owned particles
        // near it): with them, every pair counts.
        wanted_ = s.ratesWanted && !shifting_ ? s.ratesWanted->data() : nullptr;
        if (wanted_) {
            ordered.cellWanted.assign(cells_.cellCount(), 0);
            for (std::size_t k = 0; k < n_; ++k)
                if (wanted_[cells_.sortedIndex(k)]) ordered.cellWanted[cells_.cellAt(k)] = 1;
        }
        pair_.in = {ordered.mass.data(), ordered.pressureOverDensity2.data(), ordered.density.data(), ordered.volume.data(),
                    Terms::densityGradient && n_ > 0 ? ordered.densityGradient.data()->data() : nullptr};
    }

    // Inside the parallel region, on each thread's own copy of the loop (the compiler then knows
    // that no store in the pair loop changes the models, and hoists their case-wide branches).
    void run() {
        startThread();
        copyIntoCellOrder();
        if constexpr (Terms::densityGradient) withWraps([this](auto wraps) { densityGradients(wraps); });
        withWraps([this](auto wraps) { fluidPairs(wraps); });
#pragma omp barrier
        // The scalar pass's forEachNeighbour takes the nearest image itself: one version is enough.
        if constexpr (lanes == 1)
            sumWithWallTerms(std::false_type{});
        else
            withWraps([this](auto wraps) { sumWithWallTerms(wraps); });
    }

private:
    // The loops over pairs come in two versions, chosen once per evaluation: without periodic
    // directions (wraps is std::false_type) a separation costs three instructions fewer per
    // direction (doc/performance.md, "Separations without the nearest-image term"). The wall list
    // has the same grid.
    template <class Loop>
    void withWraps(Loop&& loop) {
        if (cells_.anyPeriodic())
            loop(std::true_type{});
        else
            loop(std::false_type{});
    }

    void startThread() {
        thread_ = static_cast<std::size_t>(omp_get_thread_num());
        team_ = static_cast<std::size_t>(omp_get_num_threads());
        neighbours_.resize(64);
        // In lanes only: what the listed neighbours receive, and the candidates' squared distances.
        toNeighbour_.resize(lanes > 1 ? neighbours_.size() * (D + 1) : 0);
        distance2_.resize(lanes > 1 ? 64 : 0);
        std::vector<Vec<D>>& accelerationOfThread = ordered_.acceleration[thread_];
        accelerationOfThread.assign(n_, Vec<D>::Zero());
        accelerations_ = accelerationOfThread.data()->data();
        if constexpr (Terms::densityRate) {
            ordered_.densityRate[thread_].assign(n_, 0.0);
            densityRates_ = ordered_.densityRate[thread_].data();
        }
        if constexpr (Terms::densityGradient) {
            ordered_.gradientSums[thread_].assign(n_ * gradientSumCount, 0.0);
            gradientSums_ = ordered_.gradientSums[thread_].data();
        }
        if (shifting_) {
            shifting_->sumsOfThread[thread_].assign(n_, typename ParticleShiftingScratch<D>::Sums{});
            shiftingSums_ = shifting_->sumsOfThread[thread_].data();
            if (thread_ == 0) shifting_->summingThreads = team_;
        }
    }

    void copyIntoCellOrder() {
        double* const mass = ordered_.mass.data();
        double* const pressureOverDensity2 = ordered_.pressureOverDensity2.data();
        Vec<D>* const velocity = ordered_.velocity.data();
        double* const density = ordered_.density.data();
        double* const volume = ordered_.volume.data();
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < n_; ++k) {
            const std::size_t i = cells_.sortedIndex(k);
            mass[k] = m_[i];
            if constexpr (Terms::pressure) pressureOverDensity2[k] = p_[i] / (rho_[i] * rho_[i]);
            if constexpr (Terms::readsVelocity) velocity[k] = v_[i];
            if constexpr (Terms::readsDensity) density[k] = rho_[i];
            if constexpr (Terms::diffuses) volume[k] = m_[i] / rho_[i];
            if (shifting_) {
                shifting_->volume[k] = m_[i] / rho_[i];
                shifting_->density[k] = rho_[i];
            }
        }  // implicit barrier: the copies are complete
    }

    // The stencil of sorted place k's cell: the particles of a cell share it.
    const Stencil& fluidStencil(std::size_t k) {
        if (cells_.cellAt(k) != stencilCell_) {
            stencilCell_ = cells_.cellAt(k);
            stencil_ = cells_.stencilRanges(cells_.sortedPosition(k));
        }
        return stencil_;
    }

    // The same for the pairs: from a cell where no rate is wanted, only the cells where one is
    // (a pair of two unwanted particles adds nothing anyone uses; every pair with a wanted
    // particle is still evaluated where and when it was, so the wanted sums do not change).
    const Stencil& pairStencil(std::size_t k) {
        if (cells_.cellAt(k) != pairStencilCell_) {
            pairStencilCell_ = cells_.cellAt(k);
            const bool everyPair = !wanted_ || ordered_.cellWanted[pairStencilCell_];
            pairStencil_ =
                everyPair ? cells_.stencilRanges(cells_.sortedPosition(k)) : cells_.stencilRanges(cells_.sortedPosition(k), ordered_.cellWanted);
        }
        return pairStencil_;
    }

    // Lists the neighbours of x in neighbours_; in lanes, with room for what they receive.
    template <bool Wraps>
    std::size_t listNeighbours(const CellLinkedList<D>& list, const Stencil& around, const std::array<double, D>& x, std::size_t first) {
        const std::size_t count = list.template listWithin<lanes, Wraps>(around, x, radius_ * radius_, first, neighbours_, distance2_);
        if constexpr (lanes > 1)
            if (toNeighbour_.size() < neighbours_.size() * (D + 1)) toNeighbour_.resize(neighbours_.size() * (D + 1));
        return count;
    }

    // A kept list of sorted place k as listNeighbours would have listed it: read in place, or,
    // where lanes need room to pad it or k's cell is one where no rate is wanted, taken into
    // neighbours_, in the second case only the neighbours in cells where one is (as pairStencil).
    const std::uint32_t* keptNeighbours(const std::uint32_t* list, std::size_t& count, std::size_t k) {
        const bool everyPair = !wanted_ || ordered_.cellWanted[cells_.cellAt(k)];
        if (everyPair && lanes == 1) return list;
        if (neighbours_.size() < count + lanes) neighbours_.resize(2 * (count + lanes));
        std::size_t taken = 0;
        for (std::size_t q = 0; q < count; ++q)
            if (everyPair || ordered_.cellWanted[cells_.cellAt(list[q])]) neighbours_[taken++] = list[q];
        count = taken;
        if constexpr (lanes > 1)
            if (toNeighbour_.size() < neighbours_.size() * (D + 1)) toNeighbour_.resize(neighbours_.size() * (D + 1));
        return neighbours_.data();
    }

    std::array<double, D> sortedPosition(std::size_t k) const {
        std::array<double, D> x;
        for (int d = 0; d < D; ++d) x[d] = cells_.sortedPosition(k)[d];
        return x;
    }

    // The renormalised density gradients (Antuono2010.hpp), before any pair reads them: the sums
    // of L_i^-1 and of the density differences from each pair once, k with its later neighbours,
    // into this thread's accumulator (a pair's terms are the same for both particles but for the
    // other's volume), then per particle the threads' sums added and the gradient solved. Every
    // held pair counts, copies' included: a halo copy next to an owned particle needs its own
    // gradient whole. The lists are kept for the pair loop, whose thread takes the same particles
    // in the same order (the same static schedule), so that the cells are searched once. Where
    // only some rates are wanted the kept lists hold copy-copy pairs too, which the pair loop
    // drops as it reads them (keptNeighbours).
    template <class Wraps>
    void densityGradients(Wraps) {
        const double* const volume = ordered_.volume.data();
        const double* const density = ordered_.density.data();
        const double* const xs = n_ > 0 ? cells_.sortedPosition(0).data() : nullptr;
        double* const sums = gradientSums_;
        std::vector<std::uint32_t>& kept = ordered_.neighbourLists[thread_];
        kept.clear();
        const Kernel kernel = kernel_;
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < n_; ++k) {
            const std::array<double, D> xk = sortedPosition(k);
            const std::size_t count = listNeighbours<Wraps::value>(cells_, fluidStencil(k), xk, k + 1);
            kept.push_back(static_cast<std::uint32_t>(count));
            kept.insert(kept.end(), neighbours_.begin(), neighbours_.begin() + static_cast<std::ptrdiff_t>(count));
            const double volumeK = volume[k], densityK = density[k];
            // What a pair adds to either particle, but for the other's volume: -F r (x) r to the
            // moment, F (rho_l - rho_k) r to the differences' sum (whole matrices: packed vectors).
            Moment momentK = Moment::Zero();
            Vec<D> differencesK = Vec<D>::Zero();
            for (std::size_t q = 0; q < count; ++q) {
                const std::size_t l = neighbours_[q];
                Vec<D> r;
                for (int d = 0; d < D; ++d) r[d] = cells_.template separation<Wraps::value>(xk[d] - xs[l * D + d], d);
                const Vec<D> Fr = kernel.gradientFactor(r.norm()) * r;
                const Vec<D> differenceFr = (density[l] - densityK) * Fr;
                momentK.noalias() -= (volume[l] * Fr) * r.transpose();
                differencesK += volume[l] * differenceFr;
                double* const toL = sums + l * gradientSumCount;
                Eigen::Map<Moment>(toL).noalias() -= (volumeK * Fr) * r.transpose();
                Eigen::Map<Vec<D>>(toL + D * D) += volumeK * differenceFr;
            }
            Eigen::Map<Moment>(sums + k * gradientSumCount) += momentK;
            Eigen::Map<Vec<D>>(sums + k * gradientSumCount + D * D) += differencesK;
        }  // implicit barrier: every pair is in
        double* const gradients = n_ > 0 ? ordered_.densityGradient.data()->data() : nullptr;
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < n_; ++k) {
            Moment moment = Moment::Zero();
            Vec<D> sum = Vec<D>::Zero();
            for (std::size_t t = 0; t < team_; ++t) {
                const double* const ofThread = ordered_.gradientSums[t].data() + k * gradientSumCount;
                moment += Eigen::Map<const Moment>(ofThread);
                sum += Eigen::Map<const Vec<D>>(ofThread + D * D);
            }
            const Vec<D> gradient = moment.determinant() > 0.1 ? Vec<D>(moment.inverse() * sum) : sum;
            for (int d = 0; d < D; ++d) gradients[k * D + d] = gradient[d];
        }  // implicit barrier: every gradient is in place
    }

    // Every fluid-fluid pair once: k with its later neighbours in cell order.
    template <class Wraps>
    void fluidPairs(Wraps) {
        const Kernel kernel = kernel_;
        const FluidPairTerms<D, Terms, Viscosity, Diffusion> pair = pair_;
        const double eta2 = eta2_;
        const double* const mass = pair.in.mass;
        const double* const xs = n_ > 0 ? cells_.sortedPosition(0).data() : nullptr;  // Vec<D>: D consecutive doubles
        const double* const vs = Terms::readsVelocity && n_ > 0 ? ordered_.velocity[0].data() : nullptr;
        double* const as = accelerations_;
        [[maybe_unused]] double* const drhoK = densityRates_;
        [[maybe_unused]] const std::uint32_t* kept = Terms::densityGradient ? ordered_.neighbourLists[thread_].data() : nullptr;
#pragma omp for schedule(static) nowait
        for (std::size_t k = 0; k < n_; ++k) {
            const std::array<double, D> xk = sortedPosition(k);
            std::array<double, D> vk{};
            if constexpr (Terms::readsVelocity)
                for (int d = 0; d < D; ++d) vk[d] = vs[k * D + d];
            std::size_t count;  // the later neighbours
            const std::uint32_t* listed;
            if constexpr (Terms::densityGradient) {
                count = *kept;
                const std::uint32_t* const list = kept + 1;
                kept = list + count;
                listed = keptNeighbours(list, count, k);
            } else {
                count = listNeighbours<Wraps::value>(cells_, pairStencil(k), xk, k + 1);
                listed = neighbours_.data();  // after the listing, which may grow it
            }
            // In lanes, what k receives is summed in registers and what each neighbour receives
            // is stored beside it and added after the loop (a scatter inside the loop would keep
            // it from vectorising). The list is padded to whole vectors with k itself at weight 0
            // (every term is proportional to F, which is finite at r = 0), so that no pair is left
            // to a scalar remainder loop.
            const std::size_t padded = (count + lanes - 1) / lanes * lanes;
            for (std::size_t q = count; q < padded; ++q) neighbours_[q] = static_cast<std::uint32_t>(k);  // lanes: listed is neighbours_
            [[maybe_unused]] const std::size_t stride = neighbours_.size();
            [[maybe_unused]] double* const toL = toNeighbour_.data();  // D components of acceleration, then the density rate
            // 2D: each pair's distance, then its gradient factor, for the shifting sums (two stores
            // a pair, where a branch on the case's shifting would be one in every pair). In lanes
            // (3D) the two stores cost the forces 3-5 % in every case: the sums evaluate them.
            if (lanes == 1 && pairGeometry_.size() < 2 * padded) pairGeometry_.resize(4 * padded);
            [[maybe_unused]] double* const geometry = pairGeometry_.data();
            const PairParticle<D> particleK = pair.particle(k);
            double a0 = 0.0, a1 = 0.0, a2 = 0.0, densityRateK = 0.0;
#pragma omp simd reduction(+ : a0, a1, a2, densityRateK) if (simd : lanes > 1)
            for (std::size_t q = 0; q < padded; ++q) {
                const std::size_t l = listed[q];
                double r[D], vkl[D];
                double r2 = 0.0, vDotR = 0.0;
#pragma GCC unroll 3
                for (int d = 0; d < D; ++d) {
                    r[d] = cells_.template separation<Wraps::value>(xk[d] - xs[l * D + d], d);
                    r2 += r[d] * r[d];
                    vkl[d] = 0.0;
                    if constexpr (Terms::readsVelocity) {
                        vkl[d] = vk[d] - vs[l * D + d];
                        vDotR += vkl[d] * r[d];
                    }
                }
                const double distance = std::sqrt(r2);
                const double F = (lanes == 1 || q < count ? 1.0 : 0.0) * kernel.gradientFactor(distance);
                if constexpr (lanes == 1) {
                    geometry[q] = distance;
                    geometry[padded + q] = F;
                }
                const double inverseRegularisedR2 = 1.0 / (r2 + eta2);
                double alongR, alongV;
                pair.acceleration(particleK, l, F, r2, inverseRegularisedR2, vDotR, alongR, alongV);
                // m_l a_kl to k, -m_k a_kl to l.
                const auto accumulate = [&](int d, double& sum) {
                    double perMass = alongR * r[d];
                    if constexpr (Terms::alongVelocity) perMass += alongV * vkl[d];
                    sum += mass[l] * perMass;
                    if constexpr (lanes > 1)
                        toL[d * stride + q] = -particleK.mass * perMass;
                    else
                        as[l * D + d] -= particleK.mass * perMass;
                };
                accumulate(0, a0);
                if constexpr (D > 1) accumulate(1, a1);
                if constexpr (D > 2) accumulate(2, a2);
                if constexpr (Terms::densityRate) {
                    double toK, toNeighbourDensity;
                    pair.densityRates(particleK, l, r, F, r2, inverseRegularisedR2, vDotR, toK, toNeighbourDensity);
                    densityRateK += toK;
                    if constexpr (lanes > 1)
                        toL[D * stride + q] = toNeighbourDensity;
                    else
                        drhoK[l] += toNeighbourDensity;
                }
            }
            if constexpr (lanes > 1) addWhatNeighboursReceived(count);
            if (shifting_)
                addShiftingPairs<Wraps::value, !Terms::densityGradient, lanes == 1>(cells_, kernel, *shifting_, k, xk, listed, count,
                                                                                    {geometry, geometry + padded}, shiftingSums_);
            as[k * D] += a0;
            if constexpr (D > 1) as[k * D + 1] += a1;
            if constexpr (D > 2) as[k * D + 2] += a2;
            if constexpr (Terms::densityRate) drhoK[k] += densityRateK;
        }
    }

    // In lanes: adds to the listed neighbours what the pair loop stored beside them.
    void addWhatNeighboursReceived(std::size_t count) {
        const std::size_t stride = neighbours_.size();
        const double* const toL = toNeighbour_.data();
        for (std::size_t q = 0; q < count; ++q) {
            const std::size_t l = neighbours_[q];
            for (int d = 0; d < D; ++d) accelerations_[l * D + d] += toL[d * stride + q];
            if constexpr (Terms::densityRate) densityRates_[l] += toL[D * stride + q];
        }
    }

    // Sums the threads' accumulators, adds gravity and the fluid-wall terms (gathered per fluid
    // particle) and writes the rates in storage order.
    template <class Wraps>
    void sumWithWallTerms([[maybe_unused]] Wraps wraps) {
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < n_; ++k) {
            const std::size_t i = cells_.sortedIndex(k);
            if (i >= owned_ || (wanted_ && !wanted_[i])) continue;
            Vec<D> acceleration = bodyForce_;
            double densityRate = 0.0;
            for (std::size_t t = 0; t < team_; ++t) {
                acceleration += ordered_.acceleration[t][k];
                if constexpr (Terms::densityRate) densityRate += ordered_.densityRate[t][k];
            }
            if (cells_.cellAt(k) != wallStencilCell_) {  // the wall list has the fluid list's grid
                wallStencilCell_ = cells_.cellAt(k);
                wallStencil_ = wallCells_.anyPointNear(wallStencilCell_) ? wallCells_.stencilRanges(x_[i]) : Stencil{};
            }
            if constexpr (lanes == 1)
                addWallTerms(i, acceleration, densityRate);
            else
                addWallTermsInLanes(i, acceleration, densityRate, wraps);
            a_[i] = acceleration;
            if constexpr (Terms::continuity) drho_[i] = densityRate;
        }
    }

    // Fluid particle i's wall terms, one wall neighbour at a time.
    void addWallTerms(std::size_t i, Vec<D>& acceleration, double& densityRate) const {
        const double pOverRho2 = p_[i] / (rho_[i] * rho_[i]);
        wallCells_.forEachNeighbour(wallStencil_, x_[i], radius_, [&](std::uint32_t w, const Vec<D>& r, double r2) {
            const double F = kernel_.gradientFactor(std::sqrt(r2));
            acceleration += fluidWallAcceleration<Terms::pressure>(pair_.viscosity, r, r2, F, eta2_, pOverRho2, rho_[i], v_[i], wall_, w);
            if constexpr (Terms::densityRate) densityRate += wall_.mass[w] * F * (v_[i] - wallVelocity_[w]).dot(r);
        });
    }

    // The same in lanes, as the fluid pairs: listed, padded with the first wall neighbour at weight 0.
    template <class Wraps>
    void addWallTermsInLanes(std::size_t i, Vec<D>& acceleration, double& densityRate, Wraps) {
        const double pOverRho2 = p_[i] / (rho_[i] * rho_[i]);
        std::array<double, D> xi, vi{};
        for (int d = 0; d < D; ++d) xi[d] = x_[i][d];
        if constexpr (Terms::readsVelocity)
            for (int d = 0; d < D; ++d) vi[d] = v_[i][d];
        const std::size_t count = listNeighbours<Wraps::value>(wallCells_, wallStencil_, xi, 0);
        const std::size_t padded = (count + lanes - 1) / lanes * lanes;
        for (std::size_t q = count; q < padded; ++q) neighbours_[q] = neighbours_[0];
        const std::uint32_t* listed = neighbours_.data();
        const double* const xw = wallCells_.sortedPosition(0).data();
        const bool any = count > 0;  // then there are wall particles to point at
        [[maybe_unused]] const double* const vw = any ? wallVelocity_[0].data() : nullptr;
        [[maybe_unused]] const double* const viscousVw = Viscosity::enabled && any ? wall_.viscousVelocity[0].data() : nullptr;
        const double rhoI = rho_[i];
        const double eta2 = eta2_;
        const Kernel kernel = kernel_;
        const Viscosity viscosity = pair_.viscosity;
        double a0 = 0.0, a1 = 0.0, a2 = 0.0, densityRateI = 0.0;
#pragma omp simd reduction(+ : a0, a1, a2, densityRateI)
        for (std::size_t q = 0; q < padded; ++q) {
            const std::size_t l = listed[q], w = wallCells_.sortedIndex(l);
            double r[D];
            double r2 = 0.0, viwDotR = 0.0, vDotR = 0.0;
#pragma GCC unroll 3
            for (int d = 0; d < D; ++d) {
                r[d] = cells_.template separation<Wraps::value>(xi[d] - xw[l * D + d], d);
                r2 += r[d] * r[d];
                if constexpr (Viscosity::enabled) viwDotR += (vi[d] - viscousVw[w * D + d]) * r[d];
                if constexpr (Terms::densityRate) vDotR += (vi[d] - vw[w * D + d]) * r[d];
            }
            const double F = (q < count ? 1.0 : 0.0) * kernel.gradientFactor(std::sqrt(r2));
            double alongR = 0.0, alongV = 0.0;
            fluidWallFactors<Terms::pressure>(viscosity, viwDotR, r2, F, eta2, pOverRho2, rhoI, wall_.mass[w], wall_.pressure[w], wall_.density[w],
                                              alongR, alongV);
            const auto component = [&](int d) {
                double component = alongR * r[d];
                if constexpr (Terms::alongVelocity) component += alongV * (vi[d] - viscousVw[w * D + d]);
                return component;
            };
            a0 += component(0);
            if constexpr (D > 1) a1 += component(1);
            if constexpr (D > 2) a2 += component(2);
            if constexpr (Terms::densityRate) densityRateI += wall_.mass[w] * F * vDotR;
        }
        acceleration[0] += a0;
        if constexpr (D > 1) acceleration[1] += a1;
        if constexpr (D > 2) acceleration[2] += a2;
        densityRate += densityRateI;
    }

    const CellLinkedList<D>& cells_;
    const CellLinkedList<D>& wallCells_;
    CellOrderedFluid<D>& ordered_;
    ParticleShiftingScratch<D>* shifting_;  // null unless the shifting sums are wanted
    Kernel kernel_;
    FluidPairTerms<D, Terms, Viscosity, Diffusion> pair_;
    std::size_t n_ = 0, owned_ = 0;
    const Vec<D>* x_ = nullptr;
    const Vec<D>* v_ = nullptr;
    const double* m_ = nullptr;
    const double* rho_ = nullptr;
    const double* p_ = nullptr;
    Vec<D>* a_ = nullptr;
    double* drho_ = nullptr;
    Vec<D> bodyForce_;
    const Vec<D>* wallVelocity_ = nullptr;
    WallPairFields<D> wall_{};
    double radius_ = 0.0, eta2_ = 0.0;
    const char* wanted_ = nullptr;  // per particle, where only some rates are wanted

    // Each thread's own.
    std::size_t thread_ = 0, team_ = 1;
    std::vector<std::uint32_t> neighbours_;
    std::vector<double> toNeighbour_, distance2_, pairGeometry_;
    double* accelerations_ = nullptr;  // this thread's accumulator, D doubles per place
    double* densityRates_ = nullptr;
    double* gradientSums_ = nullptr;  // delta-SPH's, gradientSumCount doubles per place
    typename ParticleShiftingScratch<D>::Sums* shiftingSums_ = nullptr;
    std::uint32_t stencilCell_ = std::numeric_limits<std::uint32_t>::max();
    Stencil stencil_;
    std::uint32_t pairStencilCell_ = std::numeric_limits<std::uint32_t>::max();
    Stencil pairStencil_;
    std::uint32_t wallStencilCell_ = std::numeric_limits<std::uint32_t>::max();
    Stencil wallStencil_;
};

// The fluid's rates, for one instantiation of the terms; with shiftingSums, the shifting pass's
// pair sums too.
template <int D, bool Continuity, bool ViscousOnly, class Kernel, class Viscosity, class Diffusion>
void fluidRates(FluidSystem<D>& s, CellOrderedFluid<D>& ordered, ParticleShiftingScratch<D>* shiftingSums, Kernel kernel, Viscosity viscosity,
                Diffusion diffusion, const Vec<D>& gravity) {
    using Loop = FluidRatesLoop<D, FluidRateTerms<Continuity, ViscousOnly, Viscosity, Diffusion>, Kernel, Viscosity, Diffusion>;
    const Loop shared(s, ordered, shiftingSums, kernel, viscosity, diffusion, gravity);
#pragma omp parallel
    {
        Loop loop = shared;
        loop.run();
    }
}

}  // namespace
}  // namespace sph
