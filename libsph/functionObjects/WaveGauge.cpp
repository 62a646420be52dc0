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
    const std::size_t gauges = points_.size();
    std::vector<Vec<D>> origin(points_), up(gauges, up_);
    if (motion_)
        for (std::size_t k = 0; k < gauges; ++k) {
            origin[k] = motion_->at(points_[k], up_, t).position;
            up[k] = motion_->normalAt(up_, t);
        }
    const auto wet = [&](const InterpolatedFluid<D>& sample) { return sample.weight >= threshold_; };
    // The scan: a line's samples from its top downwards in steps, to the first wet one. Each
    // process walks those it answers for to its first wet one, and the topmost over the
    // processes is the line's: one collective for every gauge, and no sample below it taken.
    const auto below = [&](double s) { return std::max(0.0, s - step_); };
    std::vector<double> minusFirstWet(gauges, -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < gauges; ++k)
        for (double s = lengths_[k], n = 0.0;; s = below(s), ++n) {
            const Vec<D> x = origin[k] + s * up[k];
            if (system.answersFor(x) && wet(interpolateFluid(system, x))) {
                minusFirstWet[k] = -n;
                break;
            }
            if (s == 0.0) break;
        }
    reductions_.max(minusFirstWet);
    // The crossings bisected between the first wet sample and the one above it, every gauge's
    // middle in one collective per round.
    std::vector<double> result(gauges, 0.0), dryAt(gauges), wetAt(gauges);  // 0 where a line is dry
    std::vector<std::size_t> crossed;
    for (std::size_t k = 0; k < gauges; ++k) {
        if (std::isinf(minusFirstWet[k])) continue;
        wetAt[k] = dryAt[k] = lengths_[k];
        for (double n = -minusFirstWet[k]; n > 0.0; --n) dryAt[k] = wetAt[k], wetAt[k] = below(wetAt[k]);
        crossed.push_back(k);
    }
    std::vector<std::size_t> bisecting = crossed;
    while (true) {
        std::erase_if(bisecting, [&](std::size_t k) { return !(dryAt[k] - wetAt[k] > 4e-3 * step_); });
        if (bisecting.empty()) break;
        std::vector<double> middle(bisecting.size());
        std::vector<Vec<D>> samples(bisecting.size());
        for (std::size_t n = 0; n < bisecting.size(); ++n) {
            const std::size_t k = bisecting[n];
            middle[n] = 0.5 * (wetAt[k] + dryAt[k]);
            samples[n] = origin[k] + middle[n] * up[k];
        }
        const std::vector<InterpolatedFluid<D>> sampled = interpolateFluidAt(system, samples, reductions_);
        for (std::size_t n = 0; n < bisecting.size(); ++n) (wet(sampled[n]) ? wetAt : dryAt)[bisecting[n]] = middle[n];
    }
    for (const std::size_t k : crossed) result[k] = 0.5 * (wetAt[k] + dryAt[k]);
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
