#include "boundaryModels/DynamicBoundaryCrespo2007.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sph {

namespace {

// The wall particles' pressure from their own density by the equation of state, never below
// p(rho0) (a wall does not pull), and the velocity the viscous term sees: their own.
template <int D>
void pressureAndViscousVelocity(const BoundaryView<D>& view, std::size_t begin, std::size_t end) {
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    const double* rhoWall = view.walls[fields::density].data();
    double* pWall = view.walls[fields::pressure].data();
    Vec<D>* vViscous = view.walls.optionalData(fields::viscousVelocity);
    std::visit(
        [&](const auto& eos) {
#pragma omp parallel for schedule(static)
            for (std::size_t w = begin; w < end; ++w) {
                pWall[w] = eos.pressure(std::max(rhoWall[w], eos.rho0));
                if (vViscous) vViscous[w] = vWall[w];
            }
        },
        view.eos);
}

}  // namespace

template <int D>
void DynamicBoundaryCrespo2007<D>::updateWalls(const BoundaryView<D>& view, std::size_t begin, std::size_t end) {
    const Vec<D>* vFluid = view.fluid[fields::velocity].data();
    const double* mFluid = view.fluid[fields::mass].data();
    const Vec<D>* xWall = view.walls.position.data();
    const Vec<D>* vWall = view.walls[fields::velocity].data();
    double* drhoWall = view.walls[fields::densityRate].data();
    const double radius2 = view.supportRadius * view.supportRadius;
    // The wall particles in the order of their cell list, which has the fluid list's grid: the
    // particles of a wall cell share its stencil of fluid cells. Their fluid neighbours are listed
    // without a branch and, in 3D (many per wall particle), summed in vector lanes (AVX2: four
    // doubles), as in the pair loop (measured: doc/performance.md, "The dynamic boundary's pass in
    // lanes").
    const auto& wallCells = view.wallCells;
    constexpr std::size_t lanes = D == 3 ? 4 : 1;

    const auto densityRates = [&](const auto& kernel, auto wraps) {
        const auto& fluidCells = view.fluidCells;  // a local of this function, so the loop in lanes can see it does not change
#pragma omp parallel
        {
            std::vector<std::uint32_t> neighbours(64);
            std::vector<double> distance2;
            auto stencilCell = std::numeric_limits<std::uint32_t>::max();
            typename CellLinkedList<D>::StencilRanges stencil;
            // Vec<D> holds D consecutive doubles: the loop in lanes reads them as plain arrays.
            const double* const xf = fluidCells.sortedPosition(0).data();
            static_assert(sizeof(Vec<D>) == D * sizeof(double));
            const auto* const vf = reinterpret_cast<const double*>(vFluid);
#pragma omp for schedule(static, 256)
            for (std::size_t k = 0; k < wallCells.pointCount(); ++k) {
                const std::size_t w = wallCells.sortedIndex(k);
                if (w < begin || w >= end) continue;
                if (wallCells.cellAt(k) != stencilCell) {
                    stencilCell = wallCells.cellAt(k);
                    stencil = fluidCells.stencilRanges(xWall[w]);
                }
                std::array<double, D> xw, vw;
                for (int d = 0; d < D; ++d) {
                    xw[d] = xWall[w][d];
                    vw[d] = vWall[w][d];
                }
                const std::size_t count =
                    fluidCells.template listWithin<lanes, decltype(wraps)::value>(stencil, xw, radius2, 0, neighbours, distance2);
                const std::uint32_t* listed = neighbours.data();
                double rate = 0.0;
#pragma omp simd reduction(+ : rate) if (simd : lanes > 1)
                for (std::size_t q = 0; q < count; ++q) {
                    const std::size_t l = listed[q], f = fluidCells.sortedIndex(l);
                    double r2 = 0.0, vDotR = 0.0;
#pragma GCC unroll 3
                    for (int d = 0; d < D; ++d) {
                        const double r = fluidCells.template separation<decltype(wraps)::value>(xw[d] - xf[l * D + d], d);
                        r2 += r * r;
                        vDotR += (vw[d] - vf[f * D + d]) * r;
                    }
                    rate += mFluid[f] * kernel.gradientFactor(std::sqrt(r2)) * vDotR;
                }
                drhoWall[w] = rate;
            }
        }
    };
    std::visit(
        [&](const auto& kernel) {
            if (view.fluidCells.anyPeriodic())
                densityRates(kernel, std::true_type{});
            else
                densityRates(kernel, std::false_type{});
        },
        view.kernel);
    pressureAndViscousVelocity(view, begin, end);
}

template class DynamicBoundaryCrespo2007<1>;
template class DynamicBoundaryCrespo2007<2>;
template class DynamicBoundaryCrespo2007<3>;

}  // namespace sph
