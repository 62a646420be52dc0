#include "functionObjects/WaveGauge.hpp"

#include "functionObjects/FirstParticleSpacing.hpp"
#include "functionObjects/KernelInterpolation.hpp"
#include "functionObjects/PatchByName.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

namespace {

// How far `point` may go along the unit vector `up` before it leaves the box [lo, hi].
template <int D>
double distanceToBoundary(const Vec<D>& point, const Vec<D>& up, const Vec<D>& lo, const Vec<D>& hi) {
    double reach = std::numeric_limits<double>::max();
    for (int k = 0; k < D; ++k) {
        if (up[k] > 0.0) reach = std::min(reach, (hi[k] - point[k]) / up[k]);
        if (up[k] < 0.0) reach = std::min(reach, (lo[k] - point[k]) / up[k]);
    }
    return reach;
}

}  // namespace

template <int D>
WaveGauge<D>::WaveGauge(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions),
      points_(readSamplePoints(dict, "points", context.system, "gauge")),
      threshold_(dict.getOrDefault("threshold", 0.5)),
      patchName_(dict.getOrDefault<std::string>("patch", "")) {
    const FluidSystemView<D>& system = context.system;
    const Vec<D> g = system.gravity.full;
    if (!(g.norm() > 0.0)) dict.fail("type", "waveGauge measures against gravity, and this case has none");
    up_ = -g.normalized();
    if (!(threshold_ > 0.0 && threshold_ < 1.0))
        dict.fail("threshold", fmt::format("{:g} is not a volume fraction between 0 and 1 (exclusive); 0.5 reads a flat surface", threshold_));
    for (const Vec<D>& point : points_) {
        const double reach = distanceToBoundary(point, up_, system.domainMin, system.domainMax);
        lengths_.push_back(dict.getPositiveOrDefault("length", reach));
    }
    if (!patchName_.empty()) motion_ = patchByName(dict, "patch", patchName_, system).motion.get();
    step_ = 0.25 * firstParticleSpacing(system, reductions_).value_or(system.smoothingLength);
    std::string header = "# time";
    for (const Vec<D>& point : points_) header += fmt::format(" eta({:g})", fmt::join(point, " "));
    out_ = context.series("elevation.dat", header);
    if (const Dictionary* reference = dict.findSubDict("reference")) {
        std::vector<std::string> quantities;
        for (std::size_t k = 0; k < points_.size(); ++k) quantities.push_back(fmt::format("elevation at gauge {}", k));
        reference_.emplace(*reference, context.caseDirectory, quantities);
    }
}

template <int D>
std::string WaveGauge<D>::describe() const {
    return fmt::format("waveGauge: {} gauges, threshold {:g}, {}{}", points_.size(), threshold_,
                       patchName_.empty() ? "in the lab frame" : "moving with patch " + patchName_, reference_ ? ", " + reference_->describe() : "");
}

template <int D>
std::vector<double> WaveGauge<D>::elevations(const FluidSystemView<D>& system, double t) const {
    std::vector<double> result;
    result.reserve(points_.size());
    for (std::size_t k = 0; k < points_.size(); ++k) {
        Vec<D> point = points_[k], up = up_;
        if (motion_) {
            point = motion_->at(points_[k], up_, t).position;
            up = motion_->normalAt(up_, t);
        }
        // Downwards from the top of the line to the first wet sample, then bisected.
        const auto wet = [&](double s) {
            return interpolateFluidAt(system, std::vector<Vec<D>>{point + s * up}, reductions_)[0].weight >= threshold_;
        };
        double dry = lengths_[k], s = dry;
        while (s > 0.0 && !wet(s)) {
            dry = s;
            s = std::max(0.0, s - step_);
        }
        if (!wet(s)) {
            result.push_back(0.0);
            continue;
        }
        double wetAt = s;
        while (dry - wetAt > 4e-3 * step_) {
            const double middle = 0.5 * (wetAt + dry);
            (wet(middle) ? wetAt : dry) = middle;
        }
        result.push_back(0.5 * (wetAt + dry));
    }
    return result;
}

template <int D>
void WaveGauge<D>::execute(const FluidSystemView<D>& system, double t) {
    const std::vector<double> eta = elevations(system, t);
    out_.append(fmt::format("{:.9g} {:.9g}", t, fmt::join(eta, " ")));
    if (reference_) reference_->compare(t, eta);
}

template <int D>
std::vector<ReportedError> WaveGauge<D>::errors() const {
    return errorsOf(reference_);
}

template class WaveGauge<1>;
template class WaveGauge<2>;
template class WaveGauge<3>;

}  // namespace sph
