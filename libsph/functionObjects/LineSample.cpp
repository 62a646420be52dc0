#include "functionObjects/LineSample.hpp"

#include "io/AtomicFile.hpp"
#include "io/TimeName.hpp"
#include "physics/FluidSystem.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

template <int D>
LineSample<D>::LineSample(const Dictionary& dict, const FunctionObjectContext& context)
    : start_(dict.getVector<D>("start")), end_(dict.getVector<D>("end")), points_(dict.get<int>("points")), rho0_(context.rho0),
      directory_(context.outputDirectory) {
    if (points_ < 2) dict.fail("points", "must be at least 2, found " + std::to_string(points_));
    if (const Dictionary* reference = dict.findSubDict("hydrostaticReference")) freeSurfaceHeight_ = reference->get<double>("freeSurfaceHeight");
    std::filesystem::create_directories(directory_);
    if (freeSurfaceHeight_)
        errorOut_ = TimeSeriesFile(directory_, "error.dat", "# time L2(p - p_ref)/(rho0 g H) max|p - p_ref|/(rho0 g H)");
}

template <int D>
std::string LineSample<D>::describe() const {
    return fmt::format("lineSample: start ({:g}), end ({:g}), points {}{}", fmt::join(start_, " "), fmt::join(end_, " "), points_,
                       freeSurfaceHeight_ ? fmt::format(", hydrostatic reference H = {:g}", *freeSurfaceHeight_) : "");
}

template <int D>
std::vector<typename LineSample<D>::Sample> LineSample<D>::sample(const FluidSystem<D>& system) const {
    std::vector<Sample> samples(static_cast<std::size_t>(points_));
    const double* m = system.fluid.scalar("mass").data();
    const double* rho = system.fluid.scalar("density").data();
    const double* p = system.fluid.scalar("pressure").data();
    const Vec<D>* v = system.fluid.vector("velocity").data();
    std::visit(
        [&](const auto& kernel) {
            for (int s = 0; s < points_; ++s) {
                const Vec<D> x = start_ + (end_ - start_) * (static_cast<double>(s) / (points_ - 1));
                double weight = 0.0, pressure = 0.0, density = 0.0;
                Vec<D> velocity = Vec<D>::Zero();
                system.fluidCells().forEachNeighbour(x, system.supportRadius(), [&](std::uint32_t j, const Vec<D>&, double r2) {
                    const double w = kernel.value(std::sqrt(r2)) * m[j] / rho[j];
                    weight += w;
                    pressure += w * p[j];
                    density += w * rho[j];
                    velocity += w * v[j];
                });
                const double inverse = weight > 0.0 ? 1.0 / weight : 0.0;
                samples[static_cast<std::size_t>(s)] = {x, pressure * inverse, density * inverse, velocity * inverse};
            }
        },
        system.models().kernel);
    return samples;
}

template <int D>
void LineSample<D>::execute(const FluidSystem<D>& system, double t) {
    const std::vector<Sample> samples = sample(system);
    const Vec<D> g = system.gravityAt(t);
    const double gravity = g.norm();
    const Vec<D> up = gravity > 0.0 ? Vec<D>(-g / gravity) : Vec<D>::Zero();
    std::string csv = freeSurfaceHeight_ ? "distance,x,y,z,p,rho,Ux,Uy,Uz,p_ref\n" : "distance,x,y,z,p,rho,Ux,Uy,Uz\n";
    double sum2 = 0.0, maxError = 0.0;
    for (const Sample& s : samples) {
        csv += fmt::format("{:.9g}", (s.position - start_).norm());
        for (int d = 0; d < 3; ++d) csv += fmt::format(",{:.9g}", d < D ? s.position[d] : 0.0);
        csv += fmt::format(",{:.9g},{:.9g}", s.pressure, s.density);
        for (int d = 0; d < 3; ++d) csv += fmt::format(",{:.9g}", d < D ? s.velocity[d] : 0.0);
        if (freeSurfaceHeight_) {
            const double reference = rho0_ * gravity * (*freeSurfaceHeight_ - s.position.dot(up));
            csv += fmt::format(",{:.9g}", reference);
            sum2 += (s.pressure - reference) * (s.pressure - reference);
            maxError = std::max(maxError, std::abs(s.pressure - reference));
        }
        csv += "\n";
    }
    const auto timeDirectory = directory_ / timeName(t);
    std::filesystem::create_directories(timeDirectory);
    writeTextAtomically(timeDirectory / "line.csv", csv);
    if (freeSurfaceHeight_) {
        const double scale = rho0_ * gravity * *freeSurfaceHeight_;
        time_ = t;
        l2_ = scale > 0.0 ? std::sqrt(sum2 / points_) / scale : 0.0;
        max_ = scale > 0.0 ? maxError / scale : 0.0;
        errorOut_.append(fmt::format("{:.9g} {:.6e} {:.6e}", t, l2_, max_));
    }
}

template <int D>
std::string LineSample<D>::summary() const {
    if (!freeSurfaceHeight_) return {};
    return fmt::format("hydrostatic pressure error at t = {:g}: L2 {:.4e}, max {:.4e} (normalised by rho0 g H)", time_, l2_, max_);
}

template class LineSample<1>;
template class LineSample<2>;
template class LineSample<3>;

}  // namespace sph
