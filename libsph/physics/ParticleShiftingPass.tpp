// FluidSystem<D>::shiftParticles, included by FluidSystem.tpp. Once a step, from the state at
// its end:
//   1. sums      each fluid pair once (per-thread accumulators, ShiftingPairSums.hpp), then
//                the walls gathered per particle: the moment matrix and concentration
//                gradient of FreeSurfaceMarrone2010.hpp (lambda_i, n_i) and the law's sum
//                (FickianShiftingLind2012.hpp, ShiftingSun2017.hpp), walls completing them.
//                The pairs' sums are the force loop's where the step's last evaluation took
//                them at the state the pass reads (FluidRates.tpp): it lists the pairs anyway;
//                with delta-SPH, the moment and density differences are its gradient pass's
//   2. surface   each particle within the support of a free-surface particle takes the mean of
//                their normals (free-surface particles are few: serial)
//   3. shift     the law's velocity; near the free surface its component along that normal removed;
//                never towards a wall particle nearer than dx, of a one-layer wall or a layered one
//                (its component against that particle's normal removed: a particle through the
//                wall is lost). Both walls complete the sums, so that a particle further off is
//                shifted towards the wall where the fluid has drifted off it: removing the
//                component everywhere within the support drew the fluid off the walls (the
//                sloshing tank's level at a side wall sinking by 0.6 dx in 10 s on layers; on the
//                correction the flux through a periodic array of cylinders 14 % high after 3 s,
//                and the dam break's wall probes left in a gap); bounded; then x_i += dt delta u_i
// A particle's density, where it follows the continuity equation, takes the shift's Taylor term
// rho_i += delta r . <grad rho>_i (Lind et al.), the gradient renormalised as in delta-SPH; without
// it a shifted particle kept the density of where it came from, and the pressure of a corner the
// shift had emptied fell until the fluid ran into it (sloshingTank2D with dummy particles: a
// particle through the bottom corner at t = 8 s). The velocity is not corrected (as Sun et al.).
#include "kernels/KernelOutsideFraction.hpp"
#include "physics/ShiftingPairSums.hpp"

#include <Eigen/Eigenvalues>

namespace sph {

namespace {

// The smallest eigenvalue of a symmetric matrix, in closed form (Eigen's iterative solver is not
// needed at D <= 3).
template <int D>
double smallestEigenvalue(const Eigen::Matrix<double, D, D>& m) {
    if constexpr (D == 1) {
        return m(0, 0);
    } else if constexpr (D == 2) {
        const double mean = 0.5 * (m(0, 0) + m(1, 1)), half = 0.5 * (m(0, 0) - m(1, 1));
        return mean - std::sqrt(half * half + m(0, 1) * m(0, 1));
    } else {
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> solver;
        solver.computeDirect(m, Eigen::EigenvaluesOnly);
        return solver.eigenvalues()[0];
    }
}

// What the shifting passes read and write, gathered once per step.
template <int D>
struct ShiftingViews {
    const CellLinkedList<D>& cells;
    const CellLinkedList<D>& wallCells;
    const std::vector<Patch<D>>& patches;
    ParticleShiftingScratch<D>& scratch;
    std::size_t n;  // owned fluid particles
    double radius, dx;
    FreeSurfaceMarrone2010 surface;
    Vec<D>* x;
    const Vec<D>* v;
    const double* m;
    double* rho;  // read by the sums, corrected by the shift
    const double* wallMass;
    const double* wallDensity;
    const Vec<D>* wallNormal;
    const double* wallArea;
    bool oneLayerWalls, evolvesDensity;
    Vec<D>* shift;
    double* lambda;

    // Every surface element of a one-layer wall near x (wall-force patches).
    template <class Visit>
    void forEachWallElement(const Vec<D>& at, Visit&& visit) const {
        for (const Patch<D>& patch : patches)
            if (patch.cells) patch.cells->forEachNeighbour(at, radius, [&](std::uint32_t w, const Vec<D>& r, double r2) { visit(w, r, r2); });
    }
};

// Pass 1's sums, per thread and in cell order, where the rates' force loop did not take them:
// each fluid pair is visited once and adds to both its particles, as the force loop does
// (CellOrderedFluid.hpp). Inside the parallel region.
template <int D, class Kernel, class Wraps>
void sumShiftingPairs(const ShiftingViews<D>& in, const Kernel& kernel, std::vector<typename ParticleShiftingScratch<D>::Sums>& mine, Wraps) {
    const auto& cells = in.cells;
    const std::size_t places = cells.pointCount();
    std::vector<std::uint32_t> neighbours(64);
    std::vector<double> unusedScratch;
    auto stencilCell = std::numeric_limits<std::uint32_t>::max();
    typename CellLinkedList<D>::StencilRanges stencil;
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < places; ++k) {
        if (cells.cellAt(k) != stencilCell) {
            stencilCell = cells.cellAt(k);
            stencil = cells.stencilRanges(cells.sortedPosition(k));
        }
        std::array<double, D> xk;
        for (int d = 0; d < D; ++d) xk[d] = cells.sortedPosition(k)[d];
        const std::size_t count = cells.template listWithin<1, Wraps::value>(stencil, xk, in.radius * in.radius, k + 1, neighbours, unusedScratch);
        addShiftingPairs<Wraps::value, true, false>(cells, kernel, in.scratch, k, xk, neighbours.data(), count, {}, mine.data());
    }  // implicit barrier: every pair is in
}

// Pass 1 completed per particle: the threads' sums added, the walls', then the renormalised
// density gradient, lambda_i and, at a free-surface particle, its outward normal. Inside the
// parallel region.
template <int D, class Kernel>
void completeShiftingSums(const ShiftingViews<D>& in, const Kernel& kernel) {
    using Matrix = Eigen::Matrix<double, D, D>;
    const auto& cells = in.cells;
    ParticleShiftingScratch<D>& scratch = in.scratch;
    auto stencilCell = std::numeric_limits<std::uint32_t>::max();
    typename CellLinkedList<D>::StencilRanges wallStencil;
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < cells.pointCount(); ++k) {
        const std::size_t i = cells.sortedIndex(k);
        if (i >= in.n) continue;
        if (cells.cellAt(k) != stencilCell) {  // the wall list has the fluid list's grid
            stencilCell = cells.cellAt(k);
            wallStencil = in.wallCells.anyPointNear(stencilCell) ? in.wallCells.stencilRanges(cells.sortedPosition(k))
                                                                 : typename CellLinkedList<D>::StencilRanges{};
        }
        typename ParticleShiftingScratch<D>::Sums total;
        for (std::size_t t = 0; t < scratch.summingThreads; ++t) {
            const auto& part = scratch.sumsOfThread[t][k];
            total.gradient += part.gradient;
            total.law += part.law;
            if (scratch.momentSumsOfThread) {
                const double* const sums = (*scratch.momentSumsOfThread)[t].data() + k * (D * D + D);
                total.moment += Eigen::Map<const Matrix>(sums);
                total.densityDifferences += Eigen::Map<const Vec<D>>(sums + D * D);
            } else {
                total.moment += part.moment;
                total.densityDifferences += part.densityDifferences;
            }
        }
        Matrix& moment = total.moment;
        Vec<D>& gradient = total.gradient;
        Vec<D>& sum = total.law;
        Vec<D>& densityDifferences = total.densityDifferences;
        const Vec<D>& x = in.x[i];
        in.wallCells.forEachNeighbour(wallStencil, x, in.radius, [&](std::uint32_t w, const Vec<D>& r, double r2) {
            const double distance = std::sqrt(r2), V = in.wallMass[w] / in.wallDensity[w];
            const Vec<D> VFr = (V * kernel.gradientFactor(distance)) * r;
            moment.noalias() -= VFr * r.transpose();
            gradient += VFr;
            sum += scratch.weight(kernel.value(distance) * scratch.inverseWdx) * VFr;
            densityDifferences += (in.wallDensity[w] - in.rho[i]) * VFr;
            scratch.nearWall[i] = 1;
        });
        // Renormalised by the particles' own moment (exact for a linear field whatever the support holds).
        scratch.densityGradient[i] = std::abs(moment.determinant()) > 0.1 ? Vec<D>(moment.inverse() * densityDifferences) : densityDifferences;
        if (in.oneLayerWalls) {
            double behindWall = 0.0;
            in.forEachWallElement(x, [&](std::uint32_t w, const Vec<D>& r, double r2) {
                const double distance = std::sqrt(r2);
                const double AW = in.wallArea[w] * kernel.value(distance);
                behindWall += scratch.outsideFraction->element(distance, r.dot(in.wallNormal[w]), in.wallArea[w]);
                moment.noalias() += (AW * r) * in.wallNormal[w].transpose();
                gradient -= AW * in.wallNormal[w];
                sum -= AW * in.wallNormal[w];
                scratch.nearWall[i] = 1;
            });
            moment += behindWall * Matrix::Identity();
        }
        in.lambda[i] = smallestEigenvalue<D>(0.5 * (moment + moment.transpose()));
        scratch.outward[i] = Vec<D>::Zero();  // read only at free-surface particles
        if (in.lambda[i] < in.surface.surfaceLambda) {
            const Vec<D> inward = std::abs(moment.determinant()) > 1e-3 ? Vec<D>(moment.inverse() * gradient) : gradient;
            if (const double length = inward.norm(); length > 1e-12) scratch.outward[i] = -inward / length;
        }
        scratch.law[i] = scratch.weight.isOne() ? gradient : sum;  // a unit weight's pairs were not summed
    }
}

// Near the surface a particle's own normal is noise (its sums are nearly complete): each takes
// the kernel-weighted mean of the free-surface particles' normals around it. Free-surface
// particles are few: serial.
template <int D, class Kernel>
void spreadSurfaceNormals(const ShiftingViews<D>& in, const Kernel& kernel) {
    ParticleShiftingScratch<D>& scratch = in.scratch;
    for (std::size_t i = 0; i < in.n; ++i) {
        if (in.lambda[i] >= in.surface.surfaceLambda) continue;
        in.cells.forEachNeighbour(in.x[i], in.radius, [&](std::uint32_t j, const Vec<D>&, double r2) {
            if (j < in.n) scratch.surfaceNormal[j] += kernel.value(std::sqrt(r2)) * scratch.outward[i];
        });
    }
}

// Pass 3: the law's velocity, its component along the surface normal and towards a wall
// removed, bounded; then the move and the density's Taylor term.
template <int D, class Law>
void applyShift(const ShiftingViews<D>& in, const Law& law, double dt, double maxSpeed) {
    const ParticleShiftingScratch<D>& scratch = in.scratch;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < in.n; ++i) {
        in.shift[i] = Vec<D>::Zero();
        if (in.lambda[i] < in.surface.splashLambda) continue;
        const double speed = in.v[i].norm();
        Vec<D> u = -law.scale(speed, maxSpeed) * scratch.law[i];
        if (const double length = scratch.surfaceNormal[i].norm(); length > 0.0) {
            const Vec<D> normal = scratch.surfaceNormal[i] / length;
            u -= u.dot(normal) * normal;
        }
        if (scratch.nearWall[i]) {
            const auto awayFromWall = [&](std::uint32_t w, const Vec<D>&, double) {
                const double towards = u.dot(in.wallNormal[w]);
                if (towards < 0.0) u -= towards * in.wallNormal[w];
            };
            // The walls complete the sums: only a particle nearer than the spacing to one of
            // their particles is kept from coming nearer still.
            in.wallCells.forEachNeighbour(in.x[i], in.dx, awayFromWall);
            in.forEachWallElement(in.x[i], [&](std::uint32_t w, const Vec<D>& r, double r2) {
                if (r2 < in.dx * in.dx) awayFromWall(w, r, r2);
            });
        }
        const double bound = law.speedBound(speed, maxSpeed), magnitude = u.norm();
        if (magnitude > bound) u *= bound / magnitude;
        in.shift[i] = u;
        in.x[i] += dt * u;
        if (in.evolvesDensity) in.rho[i] += dt * u.dot(scratch.densityGradient[i]);
    }
}

}  // namespace

template <int D>
bool FluidSystem<D>::stateAsShiftingSummed() const {
    const ParticleShiftingScratch<D>& scratch = shiftingScratch_;
    const CellLinkedList<D>& cells = fluidCells_;
    const std::size_t places = cells.pointCount();
    if (!scratch.summedByRates || places != fluid.size() || scratch.density.size() != places) return false;
    const Vec<D>* x = fluid.position.data();
    const double* rho = fluid[fields::density].data();
    bool unchanged = true;
#pragma omp parallel for reduction(&& : unchanged) schedule(static)
    for (std::size_t k = 0; k < places; ++k) {
        const std::size_t i = cells.sortedIndex(k);
        unchanged = unchanged && x[i] == cells.sortedPosition(k) && rho[i] == scratch.density[k];
    }
    return unchanged;
}

template <int D>
void FluidSystem<D>::shiftParticles(double dt) {
    auto timer = timers.time(Stage::Shifting);
    // The force loop's pair sums hold where its evaluation saw this state (the last of a step,
    // at its end, for every native integrator but leapfrog): the cells are then as it left them.
    const bool summedByRates = stateAsShiftingSummed();
    shiftingScratch_.summedByRates = false;
    if (!summedByRates) fluidCells_.build(fluid.position);
    const std::size_t n = fluid.ownedCount();
    const Vec<D>* v = fluid[fields::velocity].data();
    double maxSpeed2 = 0.0;
#pragma omp parallel for reduction(max : maxSpeed2) schedule(static)
    for (std::size_t i = 0; i < n; ++i) maxSpeed2 = std::max(maxSpeed2, v[i].squaredNorm());
    if (largestOverRanks) maxSpeed2 = largestOverRanks(maxSpeed2);
    const double maxSpeed = std::sqrt(maxSpeed2);
    std::visit(
        [&](const auto& kernel, const auto& law) {
            using Law = std::decay_t<decltype(law)>;
            if constexpr (!Law::enabled) {
                return;
            } else if constexpr (!pairLoopsCompiled<D, std::decay_t<decltype(kernel)>>) {
                throw std::logic_error(pairLoopsNotCompiled);
            } else {
                const auto& cells = fluidCells_;
                const bool anyWalls = this->walls.size() > 0;
                const double* wallArea = anyWalls ? this->walls.optionalData(fields::area) : nullptr;
                const bool oneLayerWalls =
                    wallArea != nullptr && std::any_of(patches.begin(), patches.end(), [](const Patch<D>& p) { return p.cells.has_value(); });
                ParticleShiftingScratch<D>& scratch = shiftingScratch_;
                // Its table depends on the kernel alone: built at the first step that needs it.
                if (oneLayerWalls && !scratch.outsideFraction) scratch.outsideFraction.emplace(kernel);
                scratch.outward.resize(n);
                scratch.law.resize(n);
                scratch.densityGradient.resize(n);
                scratch.surfaceNormal.assign(n, Vec<D>::Zero());
                scratch.nearWall.assign(n, 0);
                const ShiftingViews<D> in{cells,
                                          wallCells_,
                                          patches,
                                          scratch,
                                          n,
                                          supportRadius_,
                                          models_.shifting.dx,
                                          models_.shifting.surface,
                                          this->fluid.position.data(),
                                          v,
                                          this->fluid[fields::mass].data(),
                                          this->fluid[fields::density].data(),
                                          anyWalls ? this->walls[fields::mass].data() : nullptr,
                                          anyWalls ? this->walls[fields::density].data() : nullptr,
                                          anyWalls ? this->walls[fields::normal].data() : nullptr,
                                          wallArea,
                                          oneLayerWalls,
                                          continuity(),
                                          this->fluid[fields::shiftingVelocity].data(),
                                          this->fluid[fields::freeSurfaceLambda].data()};
                if (!summedByRates) {
                    scratch.volume.resize(cells.pointCount());
                    scratch.density.resize(cells.pointCount());
#pragma omp parallel for schedule(static)
                    for (std::size_t l = 0; l < cells.pointCount(); ++l) {
                        const std::size_t j = cells.sortedIndex(l);
                        in.scratch.volume[l] = in.m[j] / in.rho[j];
                        in.scratch.density[l] = in.rho[j];
                    }
                    scratch.sumsOfThread.resize(static_cast<std::size_t>(omp_get_max_threads()));
                    scratch.momentSumsOfThread = nullptr;
                }
#pragma omp parallel
                {
                    if (!summedByRates) {
                        auto& mine = in.scratch.sumsOfThread[static_cast<std::size_t>(omp_get_thread_num())];
                        mine.assign(cells.pointCount(), typename ParticleShiftingScratch<D>::Sums{});
#pragma omp single
                        in.scratch.summingThreads = static_cast<std::size_t>(omp_get_num_threads());  // implicit barrier
                        if (cells.anyPeriodic())
                            sumShiftingPairs(in, kernel, mine, std::true_type{});
                        else
                            sumShiftingPairs(in, kernel, mine, std::false_type{});
                    }
                    completeShiftingSums(in, kernel);
                }
                spreadSurfaceNormals(in, kernel);
                applyShift(in, law, dt, maxSpeed);
            }
        },
        models_.kernel, models_.shifting.law);
}

}  // namespace sph
