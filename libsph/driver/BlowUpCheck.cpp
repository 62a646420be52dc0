#include "driver/BlowUpCheck.hpp"

#include "core/FatalError.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

template <int D>
void checkFluidState(const ParticleSet<D>& fluid, const Vec<D>& lo, const Vec<D>& hi, FluidStateLimits limits, long step, double t) {
    const auto& x = fluid.position;
    const auto& v = fluid[fields::velocity];
    const auto& rho = fluid[fields::density];
    const double c0 = limits.c0, rho0 = limits.rho0;
    // Written without branches, so that NaN fails it; why a particle fails is asked only of the
    // one reported.
    const auto healthy = [&](std::size_t i) {
        return (v[i].squaredNorm() <= c0 * c0) & (rho[i] >= 0.5 * rho0) & (rho[i] <= 2.0 * rho0) & (x[i].array() >= lo.array()).all() &
               (x[i].array() <= hi.array()).all();
    };
    const std::size_t n = fluid.ownedCount();
    std::size_t faulty = 0;
#pragma omp parallel for reduction(+ : faulty) schedule(static)
    for (std::size_t k = 0; k < n; ++k) faulty += !healthy(k);
    if (faulty == 0) return;
    std::size_t i = 0;
    while (healthy(i)) ++i;
    std::string what;
    if (!x[i].allFinite())
        what = "has a non-finite position";
    else if (!v[i].allFinite())
        what = "has a non-finite velocity";
    else if (v[i].squaredNorm() > c0 * c0)
        what = fmt::format("moves at {:g}, faster than the speed of sound c0 = {:g}", v[i].norm(), c0);
    else if (!(rho[i] >= 0.5 * rho0 && rho[i] <= 2.0 * rho0))
        what = fmt::format("has density {:g}, outside [0.5, 2] rho0 = [{:g}, {:g}]", rho[i], 0.5 * rho0, 2.0 * rho0);
    else
        what = fmt::format("left the domain [({:g}), ({:g})]", fmt::join(lo, " "), fmt::join(hi, " "));
    const bool leftTheDomain = what.starts_with("left");
    throw FatalError(
        fmt::format("error: the run blew up at step {}, time {:.9g}: fluid particle id {} at ({:g}) {}.\n"
                    "    The last written time is kept; reduce the time step (courant) or check the case{}.",
                    step, t, fluid.globalId[i], fmt::join(x[i], " "), what,
                    leftTheDomain ? " (a splash over the walls: enlarge the domain, or have such particles removed with "
                                    "`outOfDomain remove;` in system/controlDict)"
                                  : ""));
}

template void checkFluidState<1>(const ParticleSet<1>&, const Vec<1>&, const Vec<1>&, FluidStateLimits, long, double);
template void checkFluidState<2>(const ParticleSet<2>&, const Vec<2>&, const Vec<2>&, FluidStateLimits, long, double);
template void checkFluidState<3>(const ParticleSet<3>&, const Vec<3>&, const Vec<3>&, FluidStateLimits, long, double);

}  // namespace sph
