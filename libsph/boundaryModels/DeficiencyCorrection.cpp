#include "boundaryModels/DeficiencyCorrection.hpp"

#include "boundaryModels/DeficiencyWeightingBoundaryIntegral.hpp"
#include "boundaryModels/DeficiencyWeightingJones2010.hpp"
#include "physics/FluidSystem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sph {

template <int D, class Weighting>
DeficiencyCorrection<D, Weighting>::DeficiencyCorrection(const Dictionary& dict, const ModelContext& context, std::string typeName)
    : typeName_(std::move(typeName)) {
    const Dictionary* repulsion = dict.findSubDict("repulsion");
    if (!repulsion)
        throw FatalError(dict.where(), "patch '" + dict.name() + "': " + typeName_ +
                                           " needs a repulsion partner to stop penetration: repulsion { type monaghanKajtar; K ...; } "
                                           "or repulsion { type lennardJones; Dc ...; }");
    repulsion_ = readRepulsionLaw(*repulsion, context);
    const std::string calibration = dict.getOrDefault<std::string>("calibration", "calibrated");
    if (calibration != "calibrated" && calibration != "literal") dict.fail("calibration", "expected calibrated or literal, found '" + calibration + "'");
    literal_ = calibration == "literal";
    const std::string direction = dict.getOrDefault<std::string>("direction", "normal");
    if (direction != "normal" && direction != "radial") dict.fail("direction", "expected normal or radial, found '" + direction + "'");
    radialDirection_ = direction == "radial";
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
}

template <int D, class Weighting>
std::string DeficiencyCorrection<D, Weighting>::describe() const {
    return fmt::format("{}: calibration {}, direction {}, sample {}, temporalSmoothing {:g}, repulsion {}", typeName_,
                       literal_ ? "literal" : "calibrated", radialDirection_ ? "radial" : "normal",
                       sampleSize_ > 0 ? fmt::format("nearest {}", sampleSize_) : fmt::format("within radius {:g}", sampleRadius_), smoothing_,
                       sph::describe(repulsion_));
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::addFields(FluidSystem<D>& system) {
    system.fluid.addVector("boundaryCorrection", Vec<D>::Zero());
    system.walls.addScalar("correctionCoefficient", 0.0);
    system.walls.addVector("acceleration", Vec<D>::Zero(), false);
    if (sampleSize_ > 0) sampleRadius_ = system.supportRadius();
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::resume(const FluidSystem<D>& system, std::size_t begin, std::size_t end) {
    // All zero: the state was written with another model on this patch; start afresh.
    const auto& C = system.walls.scalar("correctionCoefficient");
    repeatWrittenCoefficients_ = std::any_of(C.begin() + static_cast<std::ptrdiff_t>(begin), C.begin() + static_cast<std::ptrdiff_t>(end),
                                             [](double c) { return c != 0.0; });
    firstEvaluation_ = !repeatWrittenCoefficients_;
}

template <int D, class Weighting>
void DeficiencyCorrection<D, Weighting>::addWallForces(FluidSystem<D>& system, const CellLinkedList<D>& patchCells, std::size_t begin,
                                                       std::size_t end, double) {
    const std::size_t n = system.fluid.ownedCount();
    const Vec<D>* x = system.fluid.position.data();
    const Vec<D>* uncorrected = system.fluid.vector("uncorrectedAcceleration").data();
    Vec<D>* a = system.fluid.vector("acceleration").data();
    Vec<D>* correction = system.fluid.vector("boundaryCorrection").data();
    const Vec<D>* xWall = system.walls.position.data();
    const Vec<D>* normal = system.walls.vector("normal").data();
    const Vec<D>* aWall = system.walls.vector("acceleration").data();
    const double* spacing = system.walls.scalar("spacing").data();
    double* C = system.walls.scalar("correctionCoefficient").data();
    const double influenceRadius = system.supportRadius();
    const double lambda = repeatWrittenCoefficients_ ? 0.0 : firstEvaluation_ ? 1.0 : smoothing_;
    firstEvaluation_ = repeatWrittenCoefficients_ = false;
    weightSum_.assign(n, 0.0);
    blend_.assign(n, Vec<D>::Zero());
    const bool radial = radialDirection_;
    const auto directionOf = [&](std::uint32_t j, const Vec<D>& r, double distance) { return radial ? Vec<D>(r / distance) : normal[j]; };

    std::visit(
        [&](const auto& kernel) {
            // Pass 1: each fluid particle's weights over Omega'_i and its blended kernel c_i.
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i) {
                double sum = 0.0;
                Vec<D> blend = Vec<D>::Zero();
                patchCells.forEachNeighbour(x[i], influenceRadius, [&](std::uint32_t j, const Vec<D>& r, double r2) {
                    const double distance = std::sqrt(r2);
                    if (distance == 0.0) return;
                    const double w = Weighting::template weight<D>(distance, Vec<D>(r / distance), normal[j], spacing[j], influenceRadius);
                    sum += w;
                    blend += (kernel.value(distance) * w) * directionOf(j, r, distance);
                });
                weightSum_[i] = sum;
                blend_[i] = (Weighting::normalised && sum > 0.0) ? Vec<D>(blend / sum) : blend;
            }
            // Pass 2: C_j from the sample of fluid particles near wall particle j.
            const auto& fluidCells = system.fluidCells();
#pragma omp parallel for schedule(static)
            for (std::size_t j = begin; j < end; ++j) {
                std::vector<std::pair<double, std::uint32_t>> candidates;
                fluidCells.forEachNeighbour(xWall[j], sampleRadius_, [&](std::uint32_t s, const Vec<D>&, double r2) { candidates.emplace_back(r2, s); });
                if (sampleSize_ > 0 && candidates.size() > static_cast<std::size_t>(sampleSize_)) {
                    std::partial_sort(candidates.begin(), candidates.begin() + sampleSize_, candidates.end());
                    candidates.resize(static_cast<std::size_t>(sampleSize_));
                }
                double numerator = 0.0, denominator = 0.0;
                for (const auto& [r2, s] : candidates) {
                    numerator += (uncorrected[s] - aWall[j]).dot(normal[j]);
                    denominator += literal_ ? kernel.value(std::sqrt(r2)) : blend_[s].dot(normal[j]);
                }
                const double fresh = denominator > 1e-12 * kernel.value(0.0) ? numerator / denominator : 0.0;
                C[j] = (1.0 - lambda) * C[j] + lambda * fresh;
            }
            // Pass 3: the blended correction.
#pragma omp parallel for schedule(static)
            for (std::size_t i = 0; i < n; ++i) {
                if (!(weightSum_[i] > 0.0)) continue;
                const double inverseSum = Weighting::normalised ? 1.0 / weightSum_[i] : 1.0;
                Vec<D> sum = Vec<D>::Zero();
                patchCells.forEachNeighbour(x[i], influenceRadius, [&](std::uint32_t j, const Vec<D>& r, double r2) {
                    const double distance = std::sqrt(r2);
                    if (distance == 0.0) return;
                    const double w = Weighting::template weight<D>(distance, Vec<D>(r / distance), normal[j], spacing[j], influenceRadius);
                    sum -= (C[j] * kernel.value(distance) * w * inverseSum) * directionOf(j, r, distance);
                });
                a[i] += sum;
                correction[i] += sum;
            }
        },
        system.models().kernel);
    addRepulsion(system, patchCells, repulsion_);
}

template class DeficiencyCorrection<1, DeficiencyWeightingJones2010>;
template class DeficiencyCorrection<2, DeficiencyWeightingJones2010>;
template class DeficiencyCorrection<3, DeficiencyWeightingJones2010>;
template class DeficiencyCorrection<1, DeficiencyWeightingBoundaryIntegral>;
template class DeficiencyCorrection<2, DeficiencyWeightingBoundaryIntegral>;
template class DeficiencyCorrection<3, DeficiencyWeightingBoundaryIntegral>;

}  // namespace sph
