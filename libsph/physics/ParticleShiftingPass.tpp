// FluidSystem<D>::shiftParticles, included by FluidSystem.tpp. Once a step, from the state at
// its end:
//   1. sums      each fluid pair once (per-thread accumulators, as the force loop), then the
//                walls gathered per particle: the moment matrix
//                and concentration gradient of FreeSurfaceMarrone2010.hpp (lambda_i, n_i) and
//                the law's sum (FickianShiftingLind2012.hpp, ShiftingSun2017.hpp), walls
//                completing them
//   2. surface   each particle within the support of a free-surface particle takes the mean of
//                their normals (free-surface particles are few: serial)
//   3. shift     the law's velocity; near the free surface its component along that normal removed;
//                towards a one-layer wall never (its component against the normal of each of its
//                particles within the support removed: a particle through the wall is lost), nor
//                towards a wall particle of a layered wall nearer than dx (their sums are complete:
//                removing the component everywhere near them drew the fluid off the walls, the
//                sloshing tank's level at a side wall sinking by 0.6 dx in 10 s); bounded; then
//                x_i += dt delta u_i
// A particle's density, where it follows the continuity equation, takes the shift's Taylor term
// rho_i += delta r . <grad rho>_i (Lind et al.), the gradient renormalised as in delta-SPH; without
// it a shifted particle kept the density of where it came from, and the pressure of a corner the
// shift had emptied fell until the fluid ran into it (sloshingTank2D with dummy particles: a
// particle through the bottom corner at t = 8 s). The velocity is not corrected (as Sun et al.).
#include "kernels/KernelOutsideFraction.hpp"

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

}  // namespace

template <int D>
void FluidSystem<D>::shiftParticles(double dt) {
    auto timer = timers.time(Stage::Shifting);
    fluidCells_.build(fluid.position);
    const std::size_t n = fluid.ownedCount();
    const Vec<D>* v = fluid.vector("velocity").data();
    double maxSpeed2 = 0.0;
#pragma omp parallel for reduction(max : maxSpeed2) schedule(static)
    for (std::size_t i = 0; i < n; ++i) maxSpeed2 = std::max(maxSpeed2, v[i].squaredNorm());
    const double maxSpeed = std::sqrt(maxSpeed2);
    std::visit(
        [&](const auto& kernel, const auto& law) {
            using Law = std::decay_t<decltype(law)>;
            if constexpr (!Law::enabled) {
                return;
            } else if constexpr (!pairLoopsCompiled<D, std::decay_t<decltype(kernel)>>) {
                throw std::logic_error(pairLoopsNotCompiled);
            } else {
                using Matrix = Eigen::Matrix<double, D, D>;
                const double radius = supportRadius_;
                const double inverseWdx = 1.0 / kernel.value(models_.shifting.dx);
                const FreeSurfaceMarrone2010 surface = models_.shifting.surface;
                const double* m = fluid.scalar("mass").data();
                const double* rho = fluid.scalar("density").data();
                const bool anyWalls = walls.size() > 0;
                const double* wallMass = anyWalls ? walls.scalar("mass").data() : nullptr;
                const double* wallDensity = anyWalls ? walls.scalar("density").data() : nullptr;
                const Vec<D>* wallNormal = anyWalls ? walls.vector("normal").data() : nullptr;
                const double* wallArea = anyWalls && walls.hasScalar("area") ? walls.scalar("area").data() : nullptr;
                const bool oneLayerWalls =
                    wallArea != nullptr && std::any_of(patches.begin(), patches.end(), [](const Patch<D>& p) { return p.cells.has_value(); });
                ParticleShiftingScratch<D>& scratch = shiftingScratch_;
                // Its table depends on the kernel alone: built at the first step that needs it.
                if (oneLayerWalls && !scratch.outsideFraction) scratch.outsideFraction.emplace(kernel);
                Vec<D>* shift = fluid.vector("shiftingVelocity").data();
                const bool evolvesDensity = continuity();
                double* density = fluid.scalar("density").data();
                const auto& cells = fluidCells_;
                scratch.volume.resize(cells.pointCount());
                scratch.outward.resize(n);
                scratch.law.resize(n);
                scratch.densityGradient.resize(n);
                scratch.surfaceNormal.assign(n, Vec<D>::Zero());
                scratch.nearWall.assign(n, 0);
                std::vector<double>& volume = scratch.volume;
                std::vector<Vec<D>>& outward = scratch.outward;
                std::vector<Vec<D>>& lawSum = scratch.law;
                std::vector<Vec<D>>& surfaceNormal = scratch.surfaceNormal;
                std::vector<Vec<D>>& densityGradient = scratch.densityGradient;
                std::vector<char>& nearWall = scratch.nearWall;
                double* lambda = fluid.scalar("freeSurfaceLambda").data();
#pragma omp parallel for schedule(static)
                for (std::size_t j = 0; j < volume.size(); ++j) volume[j] = m[j] / rho[j];
                // Every surface element of a one-layer wall near x (wall-force patches).
                const auto forEachWallElement = [&](const Vec<D>& x, auto&& visit) {
                    for (const Patch<D>& patch : patches)
                        if (patch.cells)
                            patch.cells->forEachNeighbour(x, radius, [&](std::uint32_t w, const Vec<D>& r, double r2) { visit(w, r, r2); });
                };
                // Pass 1's sums, per thread and in cell order: each fluid pair is visited once and
                // adds to both its particles, as the force loop does (CellOrderedFluid.hpp).
                using Sums = typename ParticleShiftingScratch<D>::Sums;
                const std::size_t places = cells.pointCount();
                auto& sumsOfThread = scratch.sumsOfThread;
                sumsOfThread.resize(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
                {
                    const auto team = static_cast<std::size_t>(omp_get_num_threads());
                    std::vector<Sums>& mine = sumsOfThread[static_cast<std::size_t>(omp_get_thread_num())];
                    mine.assign(places, Sums{});
                    std::vector<std::uint32_t> neighbours(64);
                    std::vector<double> unusedScratch;
                    auto stencilCell = std::numeric_limits<std::uint32_t>::max();
                    typename CellLinkedList<D>::StencilRanges stencil, wallStencil;
                    const double* const xs = places > 0 ? cells.sortedPosition(0).data() : nullptr;
                    const auto fluidPairs = [&](auto wraps) {
#pragma omp for schedule(static, 256)
                        for (std::size_t k = 0; k < places; ++k) {
                            if (cells.cellAt(k) != stencilCell) {
                                stencilCell = cells.cellAt(k);
                                stencil = cells.stencilRanges(cells.sortedPosition(k));
                            }
                            std::array<double, D> xk;
                            for (int d = 0; d < D; ++d) xk[d] = xs[k * D + d];
                            const std::size_t i = cells.sortedIndex(k);
                            const std::size_t count =
                                cells.template listWithin<1, decltype(wraps)::value>(stencil, xk, radius * radius, k + 1, neighbours, unusedScratch);
                            Sums& atK = mine[k];
                            for (std::size_t q = 0; q < count; ++q) {
                                const std::size_t l = neighbours[q], j = cells.sortedIndex(l);
                                Vec<D> r;
                                for (int d = 0; d < D; ++d) r[d] = cells.template separation<decltype(wraps)::value>(xk[d] - xs[l * D + d], d);
                                const double distance = r.norm();
                                const Vec<D> Fr = kernel.gradientFactor(distance) * r;
                                const double weight = law.pairWeight(kernel.value(distance) * inverseWdx), densityDifference = rho[j] - rho[i];
                                const Matrix outer = Fr * r.transpose();
                                Sums& atL = mine[l];
                                atK.moment.noalias() -= volume[j] * outer;
                                atL.moment.noalias() -= volume[i] * outer;
                                atK.gradient += volume[j] * Fr;
                                atL.gradient -= volume[i] * Fr;
                                atK.law += (weight * volume[j]) * Fr;
                                atL.law -= (weight * volume[i]) * Fr;
                                atK.densityDifferences += (densityDifference * volume[j]) * Fr;
                                atL.densityDifferences += (densityDifference * volume[i]) * Fr;
                            }
                        }  // implicit barrier: every pair is in
                    };
                    if (cells.anyPeriodic())
                        fluidPairs(std::true_type{});
                    else
                        fluidPairs(std::false_type{});
                    stencilCell = std::numeric_limits<std::uint32_t>::max();
#pragma omp for schedule(static, 256)
                    for (std::size_t k = 0; k < places; ++k) {
                        const std::size_t i = cells.sortedIndex(k);
                        if (i >= n) continue;
                        if (cells.cellAt(k) != stencilCell) {  // the wall list has the fluid list's grid
                            stencilCell = cells.cellAt(k);
                            wallStencil = wallCells_.anyPointNear(stencilCell) ? wallCells_.stencilRanges(cells.sortedPosition(k))
                                                                               : typename CellLinkedList<D>::StencilRanges{};
                        }
                        Sums total;
                        for (std::size_t t = 0; t < team; ++t) {
                            const Sums& part = sumsOfThread[t][k];
                            total.moment += part.moment;
                            total.gradient += part.gradient;
                            total.law += part.law;
                            total.densityDifferences += part.densityDifferences;
                        }
                        Matrix& moment = total.moment;
                        Vec<D>& gradient = total.gradient;
                        Vec<D>& sum = total.law;
                        Vec<D>& densityDifferences = total.densityDifferences;
                        const Vec<D>& x = fluid.position[i];
                        wallCells_.forEachNeighbour(wallStencil, x, radius, [&](std::uint32_t w, const Vec<D>& r, double r2) {
                            const double distance = std::sqrt(r2), V = wallMass[w] / wallDensity[w];
                            const Vec<D> VFr = (V * kernel.gradientFactor(distance)) * r;
                            moment.noalias() -= VFr * r.transpose();
                            gradient += VFr;
                            sum += law.pairWeight(kernel.value(distance) * inverseWdx) * VFr;
                            densityDifferences += (wallDensity[w] - rho[i]) * VFr;
                            nearWall[i] = 1;
                        });
                        // Renormalised by the particles' own moment (exact for a linear field whatever the support holds).
                        densityGradient[i] =
                            std::abs(moment.determinant()) > 0.1 ? Vec<D>(moment.inverse() * densityDifferences) : densityDifferences;
                        if (oneLayerWalls) {
                            double behindWall = 0.0;
                            forEachWallElement(x, [&](std::uint32_t w, const Vec<D>& r, double r2) {
                                const double distance = std::sqrt(r2);
                                const double AW = wallArea[w] * kernel.value(distance);
                                behindWall += scratch.outsideFraction->element(distance, r.dot(wallNormal[w]), wallArea[w]);
                                moment.noalias() += (AW * r) * wallNormal[w].transpose();
                                gradient -= AW * wallNormal[w];
                                sum -= AW * wallNormal[w];
                                nearWall[i] = 1;
                            });
                            moment += behindWall * Matrix::Identity();
                        }
                        lambda[i] = smallestEigenvalue<D>(0.5 * (moment + moment.transpose()));
                        outward[i] = Vec<D>::Zero();  // read only at free-surface particles
                        if (lambda[i] < surface.surfaceLambda) {
                            const Vec<D> inward = std::abs(moment.determinant()) > 1e-3 ? Vec<D>(moment.inverse() * gradient) : gradient;
                            if (const double length = inward.norm(); length > 1e-12) outward[i] = -inward / length;
                        }
                        lawSum[i] = sum;
                    }
                }
                // Near the surface a particle's own normal is noise (its sums are nearly complete):
                // each takes the kernel-weighted mean of the free-surface particles' normals around it.
                for (std::size_t i = 0; i < n; ++i) {
                    if (lambda[i] >= surface.surfaceLambda) continue;
                    cells.forEachNeighbour(fluid.position[i], radius, [&](std::uint32_t j, const Vec<D>&, double r2) {
                        if (j < n) surfaceNormal[j] += kernel.value(std::sqrt(r2)) * outward[i];
                    });
                }
#pragma omp parallel for schedule(static)
                for (std::size_t i = 0; i < n; ++i) {
                    shift[i] = Vec<D>::Zero();
                    if (lambda[i] < surface.splashLambda) continue;
                    const double speed = v[i].norm();
                    Vec<D> u = -law.scale(speed, maxSpeed) * lawSum[i];
                    if (const double length = surfaceNormal[i].norm(); length > 0.0) {
                        const Vec<D> normal = surfaceNormal[i] / length;
                        u -= u.dot(normal) * normal;
                    }
                    if (nearWall[i]) {
                        const auto awayFromWall = [&](std::uint32_t w, const Vec<D>&, double) {
                            const double towards = u.dot(wallNormal[w]);
                            if (towards < 0.0) u -= towards * wallNormal[w];
                        };
                        // Layers of wall particles complete the sums: only a particle nearer than
                        // the spacing to one of them is kept from coming nearer still.
                        wallCells_.forEachNeighbour(fluid.position[i], models_.shifting.dx, awayFromWall);
                        forEachWallElement(fluid.position[i], awayFromWall);
                    }
                    const double bound = law.speedBound(speed, maxSpeed), magnitude = u.norm();
                    if (magnitude > bound) u *= bound / magnitude;
                    shift[i] = u;
                    fluid.position[i] += dt * u;
                    if (evolvesDensity) density[i] += dt * u.dot(densityGradient[i]);
                }
            }
        },
        models_.kernel, models_.shifting.law);
}

}  // namespace sph
