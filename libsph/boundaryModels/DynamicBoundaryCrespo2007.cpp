#include "boundaryModels/DynamicBoundaryCrespo2007.hpp"

#include "physics/FluidSystem.hpp"

#include <cmath>

namespace sph {

template <int D>
void DynamicBoundaryCrespo2007<D>::updateWalls(FluidSystem<D>& system, std::size_t begin, std::size_t end, double) {
    const Vec<D>* vFluid = system.fluid.vector("velocity").data();
    const double* mFluid = system.fluid.scalar("mass").data();
    const Vec<D>* xWall = system.walls.position.data();
    const Vec<D>* vWall = system.walls.vector("velocity").data();
    const double* rhoWall = system.walls.scalar("density").data();
    double* drhoWall = system.walls.scalar("densityRate").data();
    double* pWall = system.walls.scalar("pressure").data();
    Vec<D>* vViscous = system.walls.hasVector("viscousVelocity") ? system.walls.vector("viscousVelocity").data() : nullptr;
    const double radius = system.supportRadius();
    const auto& cells = system.fluidCells();

    std::visit(
        [&](const auto& kernel, const auto& eos) {
#pragma omp parallel for schedule(static)
            for (std::size_t w = begin; w < end; ++w) {
                double rate = 0.0;
                cells.forEachNeighbour(xWall[w], radius, [&](std::uint32_t f, const Vec<D>& r, double r2) {
                    rate += mFluid[f] * kernel.gradientFactor(std::sqrt(r2)) * (vWall[w] - vFluid[f]).dot(r);
                });
                drhoWall[w] = rate;
                pWall[w] = eos.pressure(std::max(rhoWall[w], eos.rho0));
                if (vViscous) vViscous[w] = vWall[w];
            }
        },
        system.models().kernel, system.models().eos);
}

template class DynamicBoundaryCrespo2007<1>;
template class DynamicBoundaryCrespo2007<2>;
template class DynamicBoundaryCrespo2007<3>;

}  // namespace sph
