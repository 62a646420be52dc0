#include "functionObjects/WallPressureSensors.hpp"

#include "boundaryModels/WallPressureExtrapolation.hpp"
#include "functionObjects/PatchByName.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

template <int D>
WallPressureSensors<D>::WallPressureSensors(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : points_(dict.getVectorList<D>("points")), window_(dict.getPositiveOrDefault("timeWindow", 0.0)), patchName_(dict.get<std::string>("patch")) {
    const FluidSystemView<D>& system = context.system;
    if (points_.empty()) dict.fail("points", "lists no sensor");
    const Patch<D>* patch = &patchByName(dict, "patch", patchName_, system);
    const auto source = dict.getOrDefault<std::string>("source", "model");
    if (source != "model" && source != "fluid")
        dict.fail("source", fmt::format("unknown source '{}'; valid sources are: model (the model's wall pressure where it sets one), fluid "
                                        "(the fluid extrapolated to the wall particles)",
                                        source));
    modelSetsPressure_ = source == "model" && patch->model->setsWallPressure();

    // The patch's particles on the wall surface, where it was generated.
    const auto& walls = system.walls;
    const auto& x0 = walls.has(fields::initialPosition) ? walls[fields::initialPosition] : walls.position;
    const auto& n0 = walls.has(fields::initialNormal) ? walls[fields::initialNormal] : walls[fields::normal];
    const std::vector<int>* layer = walls.has(fields::layer) ? &walls[fields::layer] : nullptr;
    std::vector<std::size_t> surface;
    double spacing = 0.0;
    for (std::size_t j = patch->begin; j < patch->end; ++j)
        if (!layer || (*layer)[j] == 0) {
            surface.push_back(j);
            if (walls.has(fields::spacing)) spacing = std::max(spacing, walls[fields::spacing][j]);
        }
    if (surface.empty()) dict.fail("patch", fmt::format("patch '{}' has no wall particles", patchName_));
    size_ = dict.getPositiveOrDefault("size", spacing);
    for (std::size_t k = 0; k < points_.size(); ++k) {
        std::size_t nearest = surface.front();
        for (const std::size_t j : surface)
            if ((x0[j] - points_[k]).norm() < (x0[nearest] - points_[k]).norm()) nearest = j;
        const double gap = (x0[nearest] - points_[k]).norm();
        if (gap > 0.5 * size_ + spacing)
            dict.fail("points", fmt::format("sensor {} at ({:g}) is {:g} from the surface of patch '{}' (nearest wall particle at ({:g})); "
                                            "place sensors on the wall",
                                            k, fmt::join(points_[k], " "), gap, patchName_, fmt::join(x0[nearest], " ")));
        // The footprint lies in the wall's plane at the sensor, normal to its nearest particle's
        // normal: a particle of layer 0 on a layered wall lies half a spacing behind the surface,
        // which a distance in space would count against it, and a corner particle beside the
        // sensor does not lie in that plane.
        const Vec<D> normal = n0[nearest];
        std::vector<std::size_t> members;
        for (const std::size_t j : surface) {
            const Vec<D> offset = x0[j] - points_[k];
            const double across = offset.dot(normal);
            if ((offset - across * normal).norm() <= 0.5 * size_ && std::abs(across) <= std::max(spacing, 0.5 * size_)) members.push_back(j);
        }
        if (members.empty()) members.push_back(nearest);  // a sensor smaller than the spacing
        members_.push_back(std::move(members));
    }

    std::string header = "# time";
    for (const Vec<D>& point : points_) header += fmt::format(" p({:g})", fmt::join(point, " "));
    if (window_ > 0.0)
        for (const Vec<D>& point : points_) header += fmt::format(" pAveraged({:g})", fmt::join(point, " "));
    out_ = TimeSeriesFile(context.outputDirectory, "pressure.dat", header);
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
    for (const auto& members : members_) particles += members.size();
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
    const auto& wallPressure = system.walls[fields::pressure];
    const std::vector<double>* area = system.walls.has(fields::area) ? &system.walls[fields::area] : nullptr;
    std::vector<double> result;
    for (const auto& members : members_) {
        double weighted = 0.0, areaSum = 0.0, plain = 0.0;
        for (const std::size_t j : members) {
            const double pj = modelSetsPressure_ ? wallPressure[j] : extrapolatedPressure(system, j, t);
            const double A = area ? (*area)[j] : 0.0;
            weighted += A * pj;
            areaSum += A;
            plain += pj;
        }
        result.push_back(areaSum > 0.0 ? weighted / areaSum : plain / static_cast<double>(members.size()));
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
