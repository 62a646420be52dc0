#include "boundaryModels/DummyParticlesAdami2012.hpp"

#include "boundaryModels/WallPressureExtrapolation.hpp"

#include <cmath>
#include <limits>

namespace sph {

template <int D>
DummyParticlesAdami2012<D>::DummyParticlesAdami2012(const Dictionary& dict, const ModelContext& context)
    : noSlip_(dict.getOrDefault("noSlip", !context.artificialViscosity)), clampNegativePressure_(dict.getOrDefault("clampNegativePressure", true)) {
    if (noSlip_ && context.artificialViscosity)
        dict.warn("noSlip",
                  "a no-slip wall with artificial viscosity brakes the flow (Monaghan's term is no shear stress): impacts arrive late "
                  "and wall pressures read low (the standard 2D dam break: Delta T = 0.29 late, 35 % low); noSlip no, the default "
                  "with artificial viscosity, gives the loads; a no-slip wall wants viscosity laminar (doc/models.md)");
}

template <int D>
std::string DummyParticlesAdami2012<D>::describe() const {
    return std::string("dummyParticles: noSlip ") + (noSlip_ ? "yes" : "no") + ", clampNegativePressure " + (clampNegativePressure_ ? "yes" : "no");
}

template <int D>
void DummyParticlesAdami2012<D>::updateWalls(const BoundaryView<D>& view, std::size_t begin, std::size_t end) {
    const Vec<D>& gravity = view.gravity;
    const Vec<D>* aWall = view.walls.optionalData(fields::acceleration);  // none: fixed walls
    const Vec<D>* vFluid = view.fluid[fields::velocity].data();
    const double* pFluid = view.fluid[fields::pressure].data();
    const double* rhoFluid = view.fluid[fields::density].data();
    const Vec<D>* xWall = view.walls.position.data();
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    double* pWall = view.walls[fields::pressure].data();
    double* rhoWall = view.walls[fields::density].data();
    Vec<D>* vViscous = view.walls.optionalData(fields::viscousVelocity);
    const double radius = view.supportRadius;
    const auto& cells = view.fluidCells;

    std::visit(
        [&](const auto& kernel, const auto& eos) {
            const double pMin = clampNegativePressure_ ? eos.p0 : -std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static)
            for (std::size_t w = begin; w < end; ++w) {
                WallPressureExtrapolation<D> extrapolation;
                Vec<D> velocitySum = Vec<D>::Zero();
                cells.forEachNeighbour(xWall[w], radius, [&](std::uint32_t f, const Vec<D>& r, double r2) {
                    const double W = kernel.value(std::sqrt(r2));
                    extrapolation.add(W, pFluid[f], rhoFluid[f], r);
                    velocitySum += W * vFluid[f];
                });
                if (extrapolation.weight > 0.0) {
                    pWall[w] = std::max(extrapolation.pressure(aWall ? Vec<D>(gravity - aWall[w]) : gravity), pMin);
                    const Vec<D> smoothed = velocitySum / extrapolation.weight;
                    if (vViscous) vViscous[w] = noSlip_ ? Vec<D>(2.0 * vWall[w] - smoothed) : smoothed;
                } else {
                    pWall[w] = eos.p0;
                    if (vViscous) vViscous[w] = vWall[w];
                }
                // The inverse Tait law has no solution below p0 - B; keep the density positive.
                rhoWall[w] = eos.density(std::max(pWall[w], eos.p0 - 0.999 * eos.stiffness()));
            }
        },
        view.kernel, view.eos);
}

template class DummyParticlesAdami2012<1>;
template class DummyParticlesAdami2012<2>;
template class DummyParticlesAdami2012<3>;

}  // namespace sph
