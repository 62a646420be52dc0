#include "boundaryModels/DeficiencyCorrection.hpp"

#include "boundaryModels/DeficiencyWeightingBoundaryIntegral.hpp"
#include "boundaryModels/DeficiencyWeightingJones2010.hpp"
#include "boundaryModels/WallPressureExtrapolation.hpp"
#include "neighbourSearch/WallSide.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sph {

namespace {

DeficiencyCalibration readCalibration(const Dictionary& dict) {
    const std::string calibration = dict.getOrDefault<std::string>("calibration", "wallPressure");
    if (calibration == "wallPressure") return DeficiencyCalibration::WallPressure;
    if (calibration == "calibrated") return DeficiencyCalibration::Calibrated;
    if (calibration == "literal") return DeficiencyCalibration::Literal;
    dict.fail("calibration", "expected wallPressure, calibrated or literal, found '" + calibration + "'");
}

const char* calibrationName(DeficiencyCalibration calibration) {
    switch (calibration) {
        case DeficiencyCalibration::WallPressure: return "wallPressure";
        case DeficiencyCalibration::Calibrated: return "calibrated";
        case DeficiencyCalibration::Literal: return "literal";
    }
    return "";
}

// The nearest `size` of the candidates (distance^2, index), and every candidate tied with the
// last of them to round-off, so the sample never depends on storage order.
void keepNearest(std::vector<std::pair<double, std::uint32_t>>& candidates, int size) {
    const auto k = static_cast<std::size_t>(size);
    if (candidates.size() <= k) return;
    std::nth_element(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(k - 1), candidates.end());
    const double tied = candidates[k - 1].first * (1.0 + 1e-9);
    const auto last = std::partition(candidates.begin() + static_cast<std::ptrdiff_t>(k), candidates.end(),
                                     [&](const auto& candidate) { return candidate.first <= tied; });
    candidates.erase(last, candidates.end());
}

// The flux through wall particle j's element (area A, centre at x_i - r) summed over sub-elements
// across it, 5 along a 2D wall's segment and 3 x 3 on a 3D wall's square (their centres' steps
// along the element, `axes`: elementAxes), not at its centre alone: the first fluid row lies half
// a spacing from the wall, nearer the centre than the element is wide, and the centre alone gave
// a linear shear flow's first row 17 % more stress than the virtual particles' integral (a
// Poiseuille flow at H/dx = 20 lost 4.5 % of its speed). The sub-elements only where the particle
// is near left the stress 7 % (2D) and 11-20 % (3D) low.
template <int D>
double subdividedFlux(const KernelOutsideFraction<D>& flux, const Vec<D>& r, double height, const std::array<Vec<D>, 2>& axes, double area) {
    if constexpr (D == 1) {
        return flux.element(std::abs(r[0]), height, area);
    } else if constexpr (D == 2) {
        double sum = 0.0;
        for (int a = -2; a <= 2; ++a) sum += flux.elementPerAreaAndHeight((r - a * axes[0]).squaredNorm());
        return sum * 0.2 * area * height;
    } else {
        double sum = 0.0;
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b) sum += flux.elementPerAreaAndHeight((r - a * axes[0] - b * axes[1]).squaredNorm());
        return sum * area / 9.0 * height;
    }
}

// The steps between the sub-elements' centres of subdividedFlux along an element of this normal
// and area: a fifth of a 2D segment, a third of a 3D square's side along two tangents.
template <int D>
std::array<Vec<D>, 2> elementAxes(const Vec<D>& normal, double area) {
    if constexpr (D == 1) {
        return {Vec<D>::Zero(), Vec<D>::Zero()};
    } else if constexpr (D == 2) {
        return {0.2 * area * Vec<D>(-normal.y(), normal.x()), Vec<D>::Zero()};
    } else {
        const Vec<D> axis = std::abs(normal.x()) < 0.9 ? Vec<D>::UnitX() : Vec<D>::UnitY();
        const Vec<D> first = normal.cross(axis).normalized(), second = normal.cross(first);
        const double third = std::sqrt(area) / 3.0;
        return {third * first, third * second};
    }
}

// Calls visit(j, stencil) for each of the patch's wall particles in the patch list's cell order,
// with the fluid's stencil around its cell: the particles of a cell share it (the two lists have
// one grid). Called inside a parallel region, it shares the particles over the threads.
template <int D, class Visit>
void forEachWallParticleWithItsFluidStencil(const CellLinkedList<D>& patchCells, const CellLinkedList<D>& fluidCells, Visit&& visit) {
    typename CellLinkedList<D>::StencilRanges stencil;
    std::uint32_t stencilCell = std::numeric_limits<std::uint32_t>::max();
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < patchCells.pointCount(); ++k) {
        if (patchCells.cellAt(k) != stencilCell) {
            stencilCell = patchCells.cellAt(k);
            stencil = fluidCells.stencilRanges(patchCells.sortedPosition(k));
        }
        visit(patchCells.sortedIndex(k), stencil);
    }
}

}  // namespace

template <int D, class Weighting>
DeficiencyCorrection<D, Weighting>::DeficiencyCorrection(const Dictionary& dict, const ModelContext& context, std::string typeName)
    : typeName_(std::move(typeName)), calibration_(readCalibration(dict)) {
    // The partner: wallDistance unless the case names a discrete force law.
    penalty_ = WallDistancePenalty{context.c0 * context.c0 / 200.0, context.dx, 0.5 * context.dx, 1.0, context.c0, 0.25 * context.dx};
    if (const Dictionary* repulsion = dict.findSubDict("repulsion")) {
        const std::string type = repulsion->get<std::string>("type");
        if (type != "wallDistance" && type != "monaghanKajtar" && type != "lennardJones")
            throw FatalError(repulsion->entry("type").tokens().front().where,
                             "unknown repulsion '" + type + "'; valid repulsion names are:\n    lennardJones\n    monaghanKajtar\n    wallDistance");
        if (type == "wallDistance") {
            penalty_.K = repulsion->getNonNegativeOrDefault("K", penalty_.K);
            penalty_.distance = repulsion->getPositiveOrDefault("distance", penalty_.distance);
            penalty_.zeta = repulsion->getNonNegativeOrDefault("damping", penalty_.zeta);
            penalty_.springDistance = repulsion->getPositiveOrDefault("springDistance", 0.5 * penalty_.distance);
            const std::string closingSpeed = repulsion->getOrDefault<std::string>("closingSpeed", "mean");
            if (closingSpeed != "each" && closingSpeed != "mean")
                repulsion->fail("closingSpeed",
                                "expected mean (the wall particles' mean, the default) or each (each wall particle's), found '" + closingSpeed + "'");
            penalty_.meanClosingSpeed = closingSpeed == "mean";
            if (penalty_.springDistance > penalty_.distance)
                repulsion->fail("springDistance",
                                fmt::format("must not exceed distance {:g}, found {:g}", penalty_.distance, penalty_.springDistance));
        } else {
            repulsion_ = readRepulsionLaw(*repulsion, context);
        }
    }
    const std::string direction = dict.getOrDefault<std::string>("direction", "normal");
    if (direction != "normal" && direction != "radial") dict.fail("direction", "expected normal or radial, found '" + direction + "'");
    radialDirection_ = direction == "radial";
    const bool sampled = calibration_ != DeficiencyCalibration::WallPressure;
    const auto onlySampled = [&](const std::string& keyword) {
        if (!sampled && dict.found(keyword))
            dict.fail(keyword,
                      "applies to calibration calibrated or literal; calibration wallPressure takes every fluid particle within the "
                      "kernel support of a wall particle and has no history to smooth");
    };
    onlySampled("sample");
    onlySampled("temporalSmoothing");
    sampleSize_ = 4;
    sampleRadius_ = 0.0;  // set to the support radius in addFields
    if (const Dictionary* sample = dict.findSubDict("sample")) {
        const std::string type = sample->get<std::string>("type");
        if (type == "nearest") {
            sampleSize_ = sample->getOrDefault("size", 4);
            if (sampleSize_ < 1) sample->fail("size", fmt::format("must be at least 1, found {}", sampleSize_));
        } else if (type == "withinRadius") {
            sampleSize_ = 0;
            sampleRadius_ = sample->getPositive("radius");
        } else {
            sample->fail("type", "expected nearest or withinRadius, found '" + type + "'");
        }
    }
    smoothing_ = dict.getOrDefault("temporalSmoothing", 1.0);
    if (!(smoothing_ > 0.0 && smoothing_ <= 1.0)) dict.fail("temporalSmoothing", fmt::format("must lie in (0, 1], found {:g}", smoothing_));
    noSlip_ = dict.getOrDefault("noSlip", context.laminarViscosity);
    if (noSlip_ && !context.laminarViscosity)
        dict.fail("noSlip",
                  "a no-slip wall on the correction needs viscosity laminar in system/sphSchemes (its virtual particles carry the laminar "
                  "stress); with artificial viscosity or none its walls are free-slip: noSlip no");
    nu_ = noSlip_ ? context.nu : 0.0;
    smoothingLength_ = context.h;
    spacing_ = context.dx;
}

template <int D, class Weighting>
std::string DeficiencyCorrection<D, Weighting>::describe() const {
    std::string text =
        fmt::format("{}: calibration {}, direction {}", typeName_, calibrationName(calibration_), radialDirection_ ? "radial" : "normal");
    if (calibration_ != DeficiencyCalibration::WallPressure)
        text += fmt::format(", sample {}, temporalSmoothing {:g}",
                            sampleSize_ > 0 ? fmt::format("nearest {}", sampleSize_) : fmt::format("within radius {:g}", sampleRadius_), smoothing_);
    text += noSlip_ ? ", noSlip yes" : ", noSlip no";
    return text + ", repulsion " +
           (repulsion_ ? sph::describe(*repulsion_)
                       : fmt::format("wallDistance: K {:g}, damping {:g}, distance {:g}, springDistance {:g}, closingSpeed {}", penalty_.K,
                                     penalty_.zeta, penalty_.distance, penalty_.springDistance, penalty_.meanClosingSpeed ? "mean" : "each"));
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::addFields(const BoundaryView<D>& view) {
    view.fluid.add(fields::boundaryCorrection, Vec<D>::Zero());
    view.walls.add(fields::correctionCoefficient, 0.0);
    view.walls.add(fields::acceleration, Vec<D>::Zero(), false);
    if (sampleSize_ > 0) sampleRadius_ = view.supportRadius;
    outsideFraction_ = std::visit([](const auto& kernel) { return KernelOutsideFraction<D>(kernel); }, view.kernel);
    if (noSlip_) {
        const double regularisation = 0.01 * smoothingLength_ * smoothingLength_;
        std::visit(
            [&](const auto& kernel) {
                const auto laminar = [&](double s) { return kernel.gradientFactor(s) * s * s / (s * s + regularisation); };
                viscousFlux_ = KernelOutsideFraction<D>(kernel.supportRadius(), laminar);
                viscousDepth_ = MeanDepthBehindPlane<D>(kernel.supportRadius(), laminar);
            },
            view.kernel);
    }
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::resume(const BoundaryView<D>& view, std::size_t begin, std::size_t end) {
    // All zero: the state was written with another model on this patch; start afresh.
    const auto& C = view.walls[fields::correctionCoefficient];
    repeatWrittenCoefficients_ =
        calibration_ != DeficiencyCalibration::WallPressure &&
        std::any_of(C.begin() + static_cast<std::ptrdiff_t>(begin), C.begin() + static_cast<std::ptrdiff_t>(end), [](double c) { return c != 0.0; });
    firstEvaluation_ = !repeatWrittenCoefficients_;
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::addWallForces(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, std::size_t /*begin*/,
                                                       std::size_t end) {
    const std::size_t n = view.fluid.ownedCount();
    const Vec<D>& gravity = view.gravity;
    const double lambda = repeatWrittenCoefficients_ ? 0.0 : firstEvaluation_ ? 1.0 : smoothing_;
    firstEvaluation_ = repeatWrittenCoefficients_ = false;
    weightSum_.assign(n, 0.0);
    pairRanges_.resize(n);
    pairsPerThread_.resize(static_cast<std::size_t>(omp_get_max_threads()));
    blend_.assign(n, Vec<D>::Zero());
    if (separateAreaIntegral(radialDirection_)) areaIntegral_.assign(n, Vec<D>::Zero());
    push_.assign(end, 0.0);  // indexed by wall particle; [0, begin) unused
    virtualDensity_.assign(end, 0.0);
    // The case's options as template parameters: the pair loops have no branch on them. Each
    // pass is compiled over what it reads only (the kernel for the first two), which keeps the
    // instantiations few.
    const auto select = [](bool option, auto&& next) { option ? next(std::true_type{}) : next(std::false_type{}); };
    const bool wallPressureCalibration = calibration_ == DeficiencyCalibration::WallPressure;
    select(radialDirection_,
           [&](auto radial) { std::visit([&](const auto& kernel) { weighPairs<decltype(radial)::value>(view, patchCells, kernel); }, view.kernel); });
    if (noSlip_) {
        wallShear_.resize(end);
        elementAxes_.resize(end);
    }
    select(wallPressureCalibration, [&](auto wallPressure) {
        select(noSlip_, [&](auto noSlip) {
            std::visit(
                [&](const auto& kernel) {
                    setWallParticles<decltype(wallPressure)::value, decltype(noSlip)::value>(view, patchCells, gravity, lambda, kernel);
                },
                view.kernel);
        });
    });
    select(radialDirection_, [&](auto radial) {
        select(wallPressureCalibration, [&](auto wallPressure) {
            select(!repulsion_, [&](auto distancePartner) {
                select(penalty_.meanClosingSpeed, [&](auto meanClosingSpeed) {
                    applyCorrection<decltype(radial)::value, decltype(wallPressure)::value, decltype(distancePartner)::value,
                                    decltype(meanClosingSpeed)::value>(view, gravity);
                });
            });
        });
    });
    if (noSlip_) applyNoSlip(view);
    if (repulsion_) addRepulsion(view, patchCells, *repulsion_);
}

template <int D, class Weighting>
template <bool Radial, class Kernel>
void DeficiencyCorrection<D, Weighting>::weighPairs(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, const Kernel& kernel) {
    constexpr bool ownAreaIntegral = separateAreaIntegral(Radial);
    const std::size_t n = view.fluid.ownedCount();
    const Vec<D>* x = view.fluid.position.data();
    const Vec<D>* normal = view.walls[fields::normal].data();
    const double* spacing = view.walls[fields::spacing].data();
    const double* area = view.walls[fields::area].data();
    const double radius = view.supportRadius;
    // Each fluid particle's weights, blend c_i and area integral g_i; the pairs are kept (in
    // this thread's list) for the correction, so the search and weights run once.
    // The fluid in cell order, so that the particles of a cell share the patch's stencil (the
    // patch list has the fluid list's grid); most fluid cells have none of the patch within reach.
    const CellLinkedList<D>& fluidCells = view.fluidCells;
#pragma omp parallel
    {
        auto& pairs = pairsPerThread_[static_cast<std::size_t>(omp_get_thread_num())];
        pairs.clear();
        typename CellLinkedList<D>::StencilRanges stencil;
        std::uint32_t stencilCell = std::numeric_limits<std::uint32_t>::max();
#pragma omp for schedule(static)
        for (std::size_t k = 0; k < fluidCells.pointCount(); ++k) {
            const std::size_t i = fluidCells.sortedIndex(k);
            if (i >= n) continue;
            if (fluidCells.cellAt(k) != stencilCell) {
                stencilCell = fluidCells.cellAt(k);
                stencil = patchCells.anyPointNear(stencilCell) ? patchCells.stencilRanges(fluidCells.sortedPosition(k))
                                                               : typename CellLinkedList<D>::StencilRanges{};
            }
            double sum = 0.0;
            Vec<D> blend = Vec<D>::Zero(), areaSum = Vec<D>::Zero();
            const auto first = static_cast<std::uint32_t>(pairs.size());
            patchCells.forEachNeighbour(stencil, x[i], radius, [&](std::uint32_t j, const Vec<D>& r, double r2) {
                const double distance = std::sqrt(r2);
                if (distance == 0.0) return;
                const double W = kernel.value(distance);
                const double w = Weighting::template weight<D>(distance, Vec<D>(r / distance), normal[j], spacing[j], area[j], radius);
                sum += w;
                blend += (W * w) * direction<Radial>(normal[j], r, distance);
                if constexpr (ownAreaIntegral) areaSum += (W * area[j]) * normal[j];
                pairs.push_back({j, W, W * w, distance, r});
            });
            pairRanges_[i] = {static_cast<std::uint32_t>(omp_get_thread_num()), first, static_cast<std::uint32_t>(pairs.size())};
            weightSum_[i] = sum;
            blend_[i] = (Weighting::normalised && sum > 0.0) ? Vec<D>(blend / sum) : blend;
            if constexpr (ownAreaIntegral) areaIntegral_[i] = areaSum;
        }
    }
}

template <int D, class Weighting>
template <bool WallPressure, bool NoSlip, class Kernel>
void DeficiencyCorrection<D, Weighting>::setWallParticles(const BoundaryView<D>& view, const CellLinkedList<D>& patchCells, const Vec<D>& gravity,
                                                          double lambda, const Kernel& kernel) {
    // The equation of state is read once per wall particle, not per pair: visited there.
    const EquationOfState& eos = view.eos;
    const double p0 = std::visit([](const auto& e) { return e.p0; }, eos);
    const double* p = view.fluid[fields::pressure].data();
    const double* rho = view.fluid[fields::density].data();
    const Vec<D>* uncorrected = WallPressure ? nullptr : view.fluid[fields::uncorrectedAcceleration].data();
    const Vec<D>* xWall = view.walls.position.data();
    const Vec<D>* normal = view.walls[fields::normal].data();
    const Vec<D>* aWall = view.walls[fields::acceleration].data();
    double* C = view.walls[fields::correctionCoefficient].data();
    double* pWall = view.walls[fields::pressure].data();
    double* rhoWall = view.walls[fields::density].data();
    const double* area = view.walls[fields::area].data();
    const Vec<D>* v = view.fluid[fields::velocity].data();
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    const double radius = view.supportRadius;
    const bool literal = calibration_ == DeficiencyCalibration::Literal;
    const Vec<D>* areaIntegral = separateAreaIntegral(radialDirection_) ? areaIntegral_.data() : blend_.data();
    const auto& fluidCells = view.fluidCells;
    // Each wall particle's pressure, density, scale R_j and push.
#pragma omp parallel
    {
        std::vector<std::pair<double, std::uint32_t>> sample;  // one per thread, reused
        forEachWallParticleWithItsFluidStencil(patchCells, fluidCells, [&](std::size_t j, const auto& stencil) {
            WallPressureExtrapolation<D> extrapolation;
            double scaleNumerator = 0.0, scaleDenominator = 0.0;
            [[maybe_unused]] double heightSum = 0.0;
            [[maybe_unused]] Vec<D> velocitySum = Vec<D>::Zero();
            fluidCells.forEachNeighbour(stencil, xWall[j], radius, [&](std::uint32_t s, const Vec<D>& r, double r2) {
                const double W = kernel.value(std::sqrt(r2));
                extrapolation.add(W, p[s], rho[s], r);
                scaleNumerator += W * areaIntegral[s].dot(normal[j]);
                scaleDenominator += W * blend_[s].dot(normal[j]);
                if constexpr (NoSlip) {
                    heightSum -= W * r.dot(normal[j]);  // r = x_j - x_s
                    velocitySum += W * v[s];
                }
            });
            // G_j: the fluid's velocity relative to the wall over its height above the wall, both
            // as the kernel weighs them around j; and the steps of j's sub-elements.
            if constexpr (NoSlip) {
                const double weight = extrapolation.weight;
                wallShear_[j] =
                    weight > 0.0 ? Vec<D>((velocitySum / weight - vWall[j]) / std::max(heightSum / weight, 0.5 * spacing_)) : Vec<D>::Zero();
                elementAxes_[j] = elementAxes(normal[j], area[j]);
            }
            const double pj = extrapolation.weight > 0.0 ? std::max(extrapolation.pressure(gravity - aWall[j]), p0) : p0;
            const double rhoj = std::visit([pj](const auto& e) { return e.density(pj); }, eos);
            const double scale = scaleDenominator > 0.0 ? scaleNumerator / scaleDenominator : 0.0;
            const double uniformCoefficient = -2.0 * pj * scale / rhoj;
            pWall[j] = pj;
            rhoWall[j] = rhoj;
            virtualDensity_[j] = rhoj * scale;
            if constexpr (WallPressure) {
                push_[j] = pj * scale / rhoj;
                C[j] = uniformCoefficient;
                return;
            }
            sample.clear();
            fluidCells.forEachNeighbour(xWall[j], sampleRadius_, [&](std::uint32_t s, const Vec<D>&, double r2) { sample.emplace_back(r2, s); });
            if (sampleSize_ > 0) keepNearest(sample, sampleSize_);
            double numerator = 0.0, denominator = 0.0;
            for (const auto& [r2, s] : sample) {
                numerator += (uncorrected[s] - aWall[j]).dot(normal[j]);
                denominator += literal ? kernel.value(std::sqrt(r2)) : blend_[s].dot(normal[j]);
            }
            // Never attracting, never more than twice the virtual particles' push.
            const double fresh = denominator > 1e-12 * kernel.value(0.0) ? std::clamp(numerator / denominator, 2.0 * uniformCoefficient, 0.0) : 0.0;
            C[j] = (1.0 - lambda) * C[j] + lambda * fresh;
            push_[j] = -C[j];
        });
    }
}

template <int D, class Weighting>
template <bool Radial, bool WallPressure, bool DistancePartner, bool MeanClosingSpeed>
void DeficiencyCorrection<D, Weighting>::applyCorrection(const BoundaryView<D>& view, const Vec<D>& gravity) {
    const std::size_t n = view.fluid.ownedCount();
    const Vec<D>* v = view.fluid[fields::velocity].data();
    const double* p = view.fluid[fields::pressure].data();
    const double* rho = view.fluid[fields::density].data();
    double* densityRate = view.continuity ? view.fluid[fields::densityRate].data() : nullptr;
    Vec<D>* a = view.fluid[fields::acceleration].data();
    Vec<D>* correction = view.fluid[fields::boundaryCorrection].data();
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    const Vec<D>* normal = view.walls[fields::normal].data();
    const Vec<D>* aWall = view.walls[fields::acceleration].data();
    const double* area = view.walls[fields::area].data();
    const double* spacing = view.walls[fields::spacing].data();
    const double* push = push_.data();
    const double* virtualDensity = virtualDensity_.data();
    // The blended correction, the virtual particles' compression, the distance partner.
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        if (!(weightSum_[i] > 0.0)) continue;
        const double inverseSum = Weighting::normalised ? 1.0 / weightSum_[i] : 1.0;
        const double ownPressureTerm = p[i] / (rho[i] * rho[i]);
        Vec<D> sum = Vec<D>::Zero();
        WallDistancePenalty::Sums<D> penalty;
        double rate = 0.0;
        const PairRange range = pairRanges_[i];
        const WallPair* pairs = pairsPerThread_[range.thread].data();
        // The partner's side of the wall is the nearest wall particle's. Fluid beyond a convex
        // edge (behind a box, above a bulge's crest) lies behind the tangent planes of the face
        // that ends there without having crossed any wall: only where it lies behind its nearest
        // wall particle's plane has it crossed; otherwise the planes it lies behind are not its
        // wall, and their gap, growing with the depth behind them, made a damper far past the
        // step's stability (SPHERIC Test 2 blew up behind the box). Nor has fluid crossed that lies
        // behind an edge particle's plane (the faces' mean normal) in front of a face beside it
        // (WallSide.hpp): a piston flush with a tank's side wall turns the edge particle's normal
        // into the side wall, and fluid in the corner between them, taking that for a crossing,
        // was pushed into the side wall and floor while it crept through the piston's face. Nor
        // has fluid over a wall's free end (a splash over an open tank's top): taken for a
        // crossing, the wall's planes pushed it back in, a wall standing a support above the top.
        [[maybe_unused]] bool crossed = false;
        if constexpr (DistancePartner) {
            const auto side = wallSide<D>(normal, spacing, nullptr, [&](auto&& visit) {
                for (std::uint32_t k = range.begin; k < range.end; ++k) visit(pairs[k].wall, pairs[k].r, pairs[k].distance * pairs[k].distance);
            });
            crossed = side && side->behind;
        }
        for (std::uint32_t k = range.begin; k < range.end; ++k) {
            const auto& [j, W, blendWeight, distance, r] = pairs[k];
            const double shape = blendWeight * inverseSum;
            const Vec<D> d = direction<Radial>(normal[j], r, distance);
            if constexpr (WallPressure) {
                sum += (shape * (ownPressureTerm * virtualDensity[j] + push[j])) * d;
                rate -= shape * virtualDensity[j] * (v[i] - vWall[j]).dot(d);
                sum -= outsideFraction_.element(distance, r.dot(normal[j]), area[j]) * (gravity - aWall[j]);
            } else {
                sum += (shape * push[j]) * d;
            }
            if constexpr (DistancePartner) {
                if (const double rDotN = r.dot(normal[j]); crossed || rDotN >= 0.0)
                    penalty_.add<MeanClosingSpeed>(penalty, W * area[j], rDotN, -(v[i] - vWall[j]).dot(normal[j]), normal[j]);
            }
        }
        if constexpr (DistancePartner)
            a[i] += penalty.weight > 0.0 ? Vec<D>(sum + penalty_.acceleration<MeanClosingSpeed>(penalty)) : sum;
        else
            a[i] += sum;
        correction[i] += sum;
        if constexpr (WallPressure)
            if (densityRate) densityRate[i] += rate;
    }
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::applyNoSlip(const BoundaryView<D>& view) {
    const std::size_t n = view.fluid.ownedCount();
    const Vec<D>* v = view.fluid[fields::velocity].data();
    const double* rho = view.fluid[fields::density].data();
    Vec<D>* a = view.fluid[fields::acceleration].data();
    Vec<D>* correction = view.fluid[fields::boundaryCorrection].data();
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    const Vec<D>* normal = view.walls[fields::normal].data();
    const double* area = view.walls[fields::area].data();
    const double* rhoWall = view.walls[fields::density].data();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        const PairRange range = pairRanges_[i];
        const WallPair* pairs = pairsPerThread_[range.thread].data();
        Vec<D> stress = Vec<D>::Zero();
        for (std::uint32_t k = range.begin; k < range.end; ++k) {
            const WallPair& pair = pairs[k];
            const std::uint32_t j = pair.wall;
            const double height = pair.r.dot(normal[j]);
            const double flux = subdividedFlux(viscousFlux_, pair.r, height, elementAxes_[j], area[j]);
            stress += (nu_ * (1.0 + rhoWall[j] / rho[i]) * flux) * (v[i] - vWall[j] + viscousDepth_(height) * wallShear_[j]);
        }
        a[i] += stress;
        correction[i] += stress;
    }
}

template class DeficiencyCorrection<1, DeficiencyWeightingJones2010>;
template class DeficiencyCorrection<2, DeficiencyWeightingJones2010>;
template class DeficiencyCorrection<3, DeficiencyWeightingJones2010>;
template class DeficiencyCorrection<1, DeficiencyWeightingBoundaryIntegral>;
template class DeficiencyCorrection<2, DeficiencyWeightingBoundaryIntegral>;
template class DeficiencyCorrection<3, DeficiencyWeightingBoundaryIntegral>;

}  // namespace sph
