#include "boundaryModels/ModifiedDynamicBoundaryEnglish2022.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sph {

// Named, not anonymous: in the sanitizer's unity build an anonymous type captured by the
// model's lambdas draws -Wsubobject-linkage.
namespace mdbc {

// Below this |det| the first-order system is too near singular to trust (as DualSPHysics).
constexpr double smallestDeterminant = 1e-3;

// The density a wall particle at x_w takes from the fluid around its ghost node x_g.
template <int D>
struct GhostNodeDensity {
    Eigen::Matrix<double, D + 1, D + 1> moments = Eigen::Matrix<double, D + 1, D + 1>::Zero();
    Eigen::Matrix<double, D + 1, 1> massSums = Eigen::Matrix<double, D + 1, 1>::Zero();

    // One fluid neighbour: volume V, mass m, r = x_g - x_f, kernel value W and gradient factor F.
    void add(double volume, double mass, const Vec<D>& r, double W, double F) {
        Eigen::Matrix<double, D + 1, 1> weights;  // W and grad W = F r
        weights[0] = W;
        weights.template tail<D>() = F * r;
        Eigen::Matrix<double, D + 1, 1> taylor;  // 1 and x_f - x_g
        taylor[0] = 1.0;
        taylor.template tail<D>() = -r;
        moments.noalias() += volume * weights * taylor.transpose();
        massSums += mass * weights;
    }

    double extrapolatedTo(const Vec<D>& offset, double rho0) const {
        if (std::abs(moments.determinant()) >= smallestDeterminant) {
            const Eigen::Matrix<double, D + 1, 1> solution = moments.inverse() * massSums;
            return solution[0] + offset.dot(solution.template tail<D>());
        }
        return moments(0, 0) > 0.0 ? massSums[0] / moments(0, 0) : rho0;
    }
};

}  // namespace mdbc

template <int D>
ModifiedDynamicBoundaryEnglish2022<D>::ModifiedDynamicBoundaryEnglish2022(const Dictionary& dict)
    : firstLayerOffset_(dict.getOrDefault("firstLayerOffset", 0.5)) {
    if (firstLayerOffset_ < 0.0)
        dict.fail("firstLayerOffset", fmt::format("found {:g}; valid: >= 0 (the generator's firstLayerOffset, 1/2 by default)", firstLayerOffset_));
}

template <int D>
std::string ModifiedDynamicBoundaryEnglish2022<D>::describe() const {
    return fmt::format("modifiedDynamicBoundary: firstLayerOffset {:g}", firstLayerOffset_);
}

template <int D>
void ModifiedDynamicBoundaryEnglish2022<D>::addFields(const BoundaryView<D>& view) {
    if (!view.walls.has(fields::layer))
        throw FatalError(
            "error: modifiedDynamicBoundary needs the wall field 'layer' (each wall particle's layer behind the surface), "
            "which the wall particle file lacks; regenerate it with generateParticles");
    const int* layer = view.walls[fields::layer].data();
    const double* spacing = view.walls[fields::spacing].data();
    for (std::size_t w = 0; w < view.walls.size(); ++w) deepest_ = std::max(deepest_, (layer[w] + firstLayerOffset_) * spacing[w]);
}

template <int D>
void ModifiedDynamicBoundaryEnglish2022<D>::updateWalls(const BoundaryView<D>& view, std::size_t begin, std::size_t end) {
    const double* rhoFluid = view.fluid[fields::density].data();
    const double* mFluid = view.fluid[fields::mass].data();
    const Vec<D>* xWall = view.walls.position.data();
    const Vec<D>* normal = view.walls[fields::normal].data();
    const double* spacing = view.walls[fields::spacing].data();
    const int* layer = view.walls[fields::layer].data();
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    double* rhoWall = view.walls[fields::density].data();
    double* pWall = view.walls[fields::pressure].data();
    Vec<D>* vViscous = view.walls.optionalData(fields::viscousVelocity);
    const double radius = view.supportRadius;
    const auto& cells = view.fluidCells;
    std::visit(
        [&](const auto& kernel, const auto& eos) {
#pragma omp parallel for schedule(static)
            for (std::size_t w = begin; w < end; ++w) {
                const double depth = (layer[w] + firstLayerOffset_) * spacing[w];
                const Vec<D> ghost = xWall[w] + 2.0 * depth * normal[w];
                mdbc::GhostNodeDensity<D> density;
                cells.forEachNeighbour(ghost, radius, [&](std::uint32_t f, const Vec<D>& r, double r2) {
                    const double distance = std::sqrt(r2);
                    density.add(mFluid[f] / rhoFluid[f], mFluid[f], r, kernel.value(distance), kernel.gradientFactor(distance));
                });
                rhoWall[w] = density.extrapolatedTo(xWall[w] - ghost, eos.rho0);
                pWall[w] = eos.pressure(std::max(rhoWall[w], eos.rho0));
                if (vViscous) vViscous[w] = vWall[w];
            }
        },
        view.kernel, view.eos);
}

template class ModifiedDynamicBoundaryEnglish2022<1>;
template class ModifiedDynamicBoundaryEnglish2022<2>;
template class ModifiedDynamicBoundaryEnglish2022<3>;

}  // namespace sph
