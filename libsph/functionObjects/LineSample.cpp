#include "functionObjects/LineSample.hpp"

#include "functionObjects/KernelInterpolation.hpp"
#include "io/AtomicFile.hpp"
#include "io/TimeName.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sph {

template <int D>
LineSample<D>::LineSample(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : start_(dict.getVector<D>("start")),
      end_(dict.getVector<D>("end")),
      points_(dict.get<int>("points")),
      rho0_(context.rho0),
      directory_(context.outputDirectory),
      reductions_(context.reductions) {
    // Each point is a line of the written .csv: ten million is far past any plot.
    constexpr int maxPoints = 10'000'000;
    if (points_ < 2 || points_ > maxPoints)
        dict.fail("points", "must be from 2 to " + std::to_string(maxPoints) + ", found " + std::to_string(points_));
    if (const Dictionary* reference = dict.findSubDict("hydrostaticReference")) hydrostatic_.emplace(*reference);
    if (reductions_.writesFiles()) std::filesystem::create_directories(directory_);
    if (const Dictionary* reference = dict.findSubDict("reference")) {
        profileField_ = reference->get<std::string>("field");
        checkInterpolatedField<D>(*reference, "field", profileField_);
        const std::string axis = reference->get<std::string>("axis");
        profileAxis_ = axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : D;
        if (profileAxis_ >= D)
            reference->fail("axis", fmt::format("expected one of x{}{} for a {}D case, found '{}'", D > 1 ? ", y" : "", D > 2 ? ", z" : "", D, axis));
        profile_.emplace(*reference, context.caseDirectory, std::vector<std::string>{profileField_ + " profile"}, ReferenceSeries::Along::Coordinate);
    }
    if (hydrostatic_) errorOut_ = context.series("error.dat", "# time L2(p - p_ref)/(rho0 g H) max|p - p_ref|/(rho0 g H)");
}

template <int D>
std::string LineSample<D>::describe() const {
    return fmt::format("lineSample: start ({:g}), end ({:g}), points {}{}{}", fmt::join(start_, " "), fmt::join(end_, " "), points_,
                       hydrostatic_ ? fmt::format(", hydrostatic reference H = {:g}", hydrostatic_->freeSurfaceHeight()) : "",
                       profile_ ? ", " + profileField_ + " against " + profile_->describe() : "");
}

template <int D>
std::vector<typename LineSample<D>::Sample> LineSample<D>::sample(const FluidSystemView<D>& system) const {
    std::vector<Vec<D>> points;
    for (int s = 0; s < points_; ++s) points.push_back(start_ + (end_ - start_) * (static_cast<double>(s) / (points_ - 1)));
    const std::vector<InterpolatedFluid<D>> sampled = interpolateFluidAt(system, points, reductions_);
    std::vector<Sample> samples;
    for (std::size_t s = 0; s < points.size(); ++s) samples.push_back({points[s], sampled[s].pressure, sampled[s].density, sampled[s].velocity});
    return samples;
}

template <int D>
void LineSample<D>::execute(const FluidSystemView<D>& system, double t) {
    const std::vector<Sample> samples = sample(system);
    const FlowConstants<D> constants{rho0_, system.gravity.at(t)};
    std::string csv = hydrostatic_ ? "distance,x,y,z,p,rho,Ux,Uy,Uz,p_ref\n" : "distance,x,y,z,p,rho,Ux,Uy,Uz\n";
    ErrorAccumulator errors;
    for (const Sample& s : samples) {
        csv += fmt::format("{:.9g}", (s.position - start_).norm());
        for (int d = 0; d < 3; ++d) csv += fmt::format(",{:.9g}", d < D ? s.position[d] : 0.0);
        csv += fmt::format(",{:.9g},{:.9g}", s.pressure, s.density);
        for (int d = 0; d < 3; ++d) csv += fmt::format(",{:.9g}", d < D ? s.velocity[d] : 0.0);
        if (hydrostatic_) {
            const double reference = hydrostatic_->pressure(s.position, t, constants);
            csv += fmt::format(",{:.9g}", reference);
            errors.add(s.pressure - reference);
        }
        csv += "\n";
    }
    if (profile_) {
        profile_->clear();
        for (const Sample& s : samples)
            profile_->compare(s.position[profileAxis_], {fieldValue(InterpolatedFluid<D>{s.pressure, s.density, s.velocity, 0.0}, profileField_)});
        time_ = t;
    }
    if (reductions_.writesFiles()) {
        const auto timeDirectory = directory_ / timeName(t);
        std::filesystem::create_directories(timeDirectory);
        writeTextAtomically(timeDirectory / "line.csv", csv);
    }
    if (hydrostatic_) {
        const double scale = rho0_ * constants.gravity.norm() * hydrostatic_->freeSurfaceHeight();
        time_ = t;
        last_ = scale > 0.0 ? errors.norms(scale) : ErrorNorms{0.0, 0.0, 0.0};
        errorOut_.append(fmt::format("{:.9g} {:.6e} {:.6e}", t, last_.l2, last_.linf));
    }
}

template <int D>
std::vector<ReportedError> LineSample<D>::errors() const {
    std::vector<ReportedError> errors;
    if (hydrostatic_) errors.push_back({"hydrostatic p", last_, fmt::format("rho0 |g| H, {} samples at t = {:g}", points_, time_)});
    for (ReportedError error : errorsOf(profile_)) {
        error.normalisation += fmt::format(" at t = {:g}", time_);
        errors.push_back(error);
    }
    return errors;
}

template class LineSample<1>;
template class LineSample<2>;
template class LineSample<3>;

}  // namespace sph
