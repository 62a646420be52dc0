#include "boundaryModels/DummyParticlesAdami2012.hpp"

#include "boundaryModels/WallPressureExtrapolation.hpp"
#include "physics/FluidSystem.hpp"

#include <cmath>
#include <limits>

namespace sph {

template <int D>
DummyParticlesAdami2012<D>::DummyParticlesAdami2012(const Dictionary& dict)
    : noSlip_(dict.getOrDefault("noSlip", true)), clampNegativePressure_(dict.getOrDefault("clampNegativePressure", true)) {}

template <int D>
std::string DummyParticlesAdami2012<D>::describe() const {
    return std::string("dummyParticles: noSlip ") + (noSlip_ ? "yes" : "no") + ", clampNegativePressure " + (clampNegativePressure_ ? "yes" : "no");
}

template <int D>
void DummyParticlesAdami2012<D>::updateWalls(FluidSystem<D>& system, std::size_t begin, std::size_t end, double t) {
    const Vec<D> gravity = system.gravityAt(t);
    const Vec<D>* aWall = system.walls.hasVector("acceleration") ? system.walls.vector("acceleration").data() : nullptr;  // none: fixed walls
    const Vec<D>* vFluid = system.fluid.vector("velocity").data();
    const double* pFluid = system.fluid.scalar("pressure").data();
    const double* rhoFluid = system.fluid.scalar("density").data();
    const Vec<D>* xWall = system.walls.position.data();
    const Vec<D>* vWall = system.walls.vector("velocity").data();
    double* pWall = system.walls.scalar("pressure").data();
    double* rhoWall = system.walls.scalar("density").data();
    Vec<D>* vViscous = system.walls.hasVector("viscousVelocity") ? system.walls.vector("viscousVelocity").data() : nullptr;
    const double radius = system.supportRadius();
    const auto& cells = system.fluidCells();

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
        system.models().kernel, system.models().eos);
}

template class DummyParticlesAdami2012<1>;
template class DummyParticlesAdami2012<2>;
template class DummyParticlesAdami2012<3>;

}  // namespace sph
