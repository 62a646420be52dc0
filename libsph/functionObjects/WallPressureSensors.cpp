#include "functionObjects/WallPressureSensors.hpp"

#include "boundaryModels/WallPressureExtrapolation.hpp"
#include "functionObjects/PatchByName.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

namespace {

// A wall particle offered as a sensor's nearest: [distance, x0 (D), n0 (D), id], as the
// candidates of all processes are gathered.
template <int D>
constexpr std::size_t candidateRecord = 2 + 2 * D;

}  // namespace

// The nearest, by distance, then by position (lexicographically, so that every process and the
// serial run choose alike between equidistant particles).
template <int D>
typename WallPressureSensors<D>::WallCandidate WallPressureSensors<D>::nearestSurfaceParticle(const FluidSystemView<D>& system,
                                                                                              const std::vector<std::size_t>& surface,
                                                                                              const Vec<D>& point) const {
    const auto& walls = system.walls;
    const auto& x0 = walls.has(fields::initialPosition) ? walls[fields::initialPosition] : walls.position;
    const auto& n0 = walls.has(fields::initialNormal) ? walls[fields::initialNormal] : walls[fields::normal];
    const auto before = [](const double* a, const double* b) { return std::lexicographical_compare(a, a + 1 + D, b, b + 1 + D); };
    std::vector<double> mine;
    for (const std::size_t j : surface) {
        std::array<double, candidateRecord<D>> record;
        record[0] = (x0[j] - point).norm();
        for (int d = 0; d < D; ++d) record[static_cast<std::size_t>(1 + d)] = x0[j][d], record[static_cast<std::size_t>(1 + D + d)] = n0[j][d];
        record.back() = static_cast<double>(walls.globalId[j]);
        if (mine.empty() || before(record.data(), mine.data())) mine.assign(record.begin(), record.end());
    }
    const std::vector<double> all = reductions_.gather(mine);
    const double* nearest = all.data();
    for (std::size_t at = 0; at < all.size(); at += candidateRecord<D>)
        if (before(&all[at], nearest)) nearest = &all[at];
    return {nearest[0], Eigen::Map<const Vec<D>>(nearest + 1), Eigen::Map<const Vec<D>>(nearest + 1 + D), nearest[1 + 2 * D]};
}

template <int D>
WallPressureSensors<D>::WallPressureSensors(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : reductions_(context.reductions),
      points_(dict.getVectorList<D>("points")),
      window_(dict.getPositiveOrDefault("timeWindow", 0.0)),
      patchName_(dict.get<std::string>("patch")) {
    const FluidSystemView<D>& system = context.system;
    if (points_.empty()) dict.fail("points", "lists no sensor");
    const Patch<D>* patch = &patchByName(dict, "patch", patchName_, system);
    const auto source = dict.getOrDefault<std::string>("source", "model");
    if (source != "model" && source != "fluid")
        dict.fail("source", fmt::format("unknown source '{}'; valid sources are: model (the model's wall pressure where it sets one), fluid "
                                        "(the fluid extrapolated to the wall particles)",
                                        source));
    modelSetsPressure_ = source == "model" && patch->model->setsWallPressure();

    // The patch's particles on the wall surface, where it was generated (those this process owns).
    patch_ = static_cast<std::size_t>(patch - system.patches.data());
    const auto& walls = system.walls;
    const auto& x0 = walls.has(fields::initialPosition) ? walls[fields::initialPosition] : walls.position;
    const std::vector<int>* layer = walls.has(fields::layer) ? &walls[fields::layer] : nullptr;
    std::vector<std::size_t> surface;
    double spacing = 0.0;
    for (std::size_t j = patch->begin; j < patch->end; ++j)
        if (system.ownsWall(j) && (!layer || (*layer)[j] == 0)) {
            surface.push_back(j);
            if (walls.has(fields::spacing)) spacing = std::max(spacing, walls[fields::spacing][j]);
        }
    spacing = reductions_.max(spacing);
    if (reductions_.sum(static_cast<double>(surface.size())) == 0.0) dict.fail("patch", fmt::format("patch '{}' has no wall particles", patchName_));
    size_ = dict.getPositiveOrDefault("size", spacing);
    for (std::size_t k = 0; k < points_.size(); ++k) {
        const WallCandidate nearest = nearestSurfaceParticle(system, surface, points_[k]);
        const Vec<D>& at = nearest.position;
        if (nearest.gap > 0.5 * size_ + spacing)
            dict.fail("points", fmt::format("sensor {} at ({:g}) is {:g} from the surface of patch '{}' (nearest wall particle at ({:g})); "
                                            "place sensors on the wall",
                                            k, fmt::join(points_[k], " "), nearest.gap, patchName_, fmt::join(at, " ")));
        // The footprint lies in the wall's plane at the sensor, normal to its nearest particle's
        // normal: a particle of layer 0 on a layered wall lies half a spacing behind the surface,
        // which a distance in space would count against it, and a corner particle beside the
        // sensor does not lie in that plane.
        const Vec<D>& normal = nearest.normal;
        std::vector<double> members;  // ids
        for (const std::size_t j : surface) {
            const Vec<D> offset = x0[j] - points_[k];
            const double across = offset.dot(normal);
            if ((offset - across * normal).norm() <= 0.5 * size_ && std::abs(across) <= std::max(spacing, 0.5 * size_))
                members.push_back(static_cast<double>(walls.globalId[j]));
        }
        members = reductions_.gather(members);
        if (members.empty()) members.push_back(nearest.id);  // a sensor smaller than the spacing
        for (const double id : members) sensorsOf_[static_cast<std::int64_t>(id)].push_back(k);
        memberCount_.push_back(members.size());
    }

    std::string header = "# time";
    for (const Vec<D>& point : points_) header += fmt::format(" p({:g})", fmt::join(point, " "));
    if (window_ > 0.0)
        for (const Vec<D>& point : points_) header += fmt::format(" pAveraged({:g})", fmt::join(point, " "));
    out_ = context.series("pressure.dat", header);
    if (const Dictionary* reference = dict.findSubDict("reference")) {
        std::vector<std::string> quantities;
        for (std::size_t k = 0; k < points_.size(); ++k)
            quantities.push_back(fmt::format("{}pressure at sensor {}", window_ > 0.0 ? "averaged " : "", k));
        reference_.emplace(*reference, context.caseDirectory, quantities);
    }
}

template <int D>
std::string WallPressureSensors<D>::describe() const {
    std::size_t particles = 0;
    for (const std::size_t count : memberCount_) particles += count;
    return fmt::format("wallPressure: {} sensors on patch {} ({} wall particles, {}), size {:g}{}{}", points_.size(), patchName_, particles,
                       modelSetsPressure_ ? "the model's wall pressure" : "the fluid extrapolated to the wall", size_,
                       window_ > 0.0 ? fmt::format(", averaged over {:g}", window_) : "", reference_ ? ", " + reference_->describe() : "");
}

template <int D>
double WallPressureSensors<D>::extrapolatedPressure(const FluidSystemView<D>& system, std::size_t wall, double t) const {
    const double* p = system.fluid[fields::pressure].data();
    const double* rho = system.fluid[fields::density].data();
    const Vec<D> wallAcceleration = system.walls.has(fields::acceleration) ? system.walls[fields::acceleration][wall] : Vec<D>::Zero();
    WallPressureExtrapolation<D> extrapolation;
    std::visit(
        [&](const auto& kernel) {
            system.fluidCells.forEachNeighbour(system.walls.position[wall], system.supportRadius, [&](std::uint32_t f, const Vec<D>& r, double r2) {
                extrapolation.add(kernel.value(std::sqrt(r2)), p[f], rho[f], r);
            });
        },
        system.kernel);
    return extrapolation.weight > 0.0 ? extrapolation.pressure(system.gravity.at(t) - wallAcceleration) : 0.0;
}

template <int D>
std::vector<double> WallPressureSensors<D>::pressures(const FluidSystemView<D>& system, double t) const {
    const auto& walls = system.walls;
    const auto& wallPressure = walls[fields::pressure];
    const std::vector<double>* area = walls.has(fields::area) ? &walls[fields::area] : nullptr;
    // Per sensor: sum A_j p_j, sum A_j, sum p_j over its particles this process owns.
    std::vector<ExactSum> sums(3 * points_.size());
    const Patch<D>& patch = system.patches[patch_];
    for (std::size_t j = patch.begin; j < patch.end; ++j) {
        const auto sensors = sensorsOf_.find(walls.globalId[j]);
        if (sensors == sensorsOf_.end() || !system.ownsWall(j)) continue;
        const double pj = modelSetsPressure_ ? wallPressure[j] : extrapolatedPressure(system, j, t);
        const double A = area ? (*area)[j] : 0.0;
        for (const std::size_t k : sensors->second) {
            sums[3 * k].add(A * pj);
            sums[3 * k + 1].add(A);
            sums[3 * k + 2].add(pj);
        }
    }
    reductions_.sum(sums);
    std::vector<double> result;
    for (std::size_t k = 0; k < points_.size(); ++k) {
        const double areaSum = sums[3 * k + 1].value();
        result.push_back(areaSum > 0.0 ? sums[3 * k].value() / areaSum : sums[3 * k + 2].value() / static_cast<double>(memberCount_[k]));
    }
    return result;
}

template <int D>
std::vector<double> WallPressureSensors<D>::averaged(double t, const std::vector<double>& values) {
    history_.emplace_back(t, values);
    const double start = t - window_;
    while (history_.size() > 2 && history_[1].first <= start) history_.pop_front();
    const double from = std::max(start, history_.front().first);
    if (!(t > from)) return values;
    // The trapezoidal rule over [from, t], the first interval cut at the window's start.
    std::vector<double> mean(values.size(), 0.0);
    for (std::size_t s = 1; s < history_.size(); ++s) {
        const auto& [t0, p0] = history_[s - 1];
        const auto& [t1, p1] = history_[s];
        const double a = std::max(t0, from);
        if (!(t1 > a)) continue;
        for (std::size_t k = 0; k < values.size(); ++k) {
            const double pa = p0[k] + (p1[k] - p0[k]) * (a - t0) / (t1 - t0);
            mean[k] += 0.5 * (t1 - a) * (pa + p1[k]);
        }
    }
    for (double& m : mean) m /= t - from;
    return mean;
}

template <int D>
void WallPressureSensors<D>::execute(const FluidSystemView<D>& system, double t) {
    const std::vector<double> p = pressures(system, t);
    if (window_ > 0.0) {
        const std::vector<double> mean = averaged(t, p);
        out_.append(fmt::format("{:.9g} {:.9g} {:.9g}", t, fmt::join(p, " "), fmt::join(mean, " ")));
        if (reference_) reference_->compare(t, mean);
    } else {
        out_.append(fmt::format("{:.9g} {:.9g}", t, fmt::join(p, " ")));
        if (reference_) reference_->compare(t, p);
    }
}

template <int D>
std::vector<ReportedError> WallPressureSensors<D>::errors() const {
    return errorsOf(reference_);
}

template class WallPressureSensors<1>;
template class WallPressureSensors<2>;
template class WallPressureSensors<3>;

}  // namespace sph
