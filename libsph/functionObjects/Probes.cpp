#include "functionObjects/Probes.hpp"

#include "functionObjects/KernelInterpolation.hpp"
#include "functionObjects/PatchByName.hpp"
#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

namespace sph {

template <int D>
Probes<D>::Probes(const Dictionary& dict, const FunctionObjectContext<D>& context)
    : points_(readSamplePoints(dict, "points", context.system, "probe")),
      patchName_(dict.getOrDefault<std::string>("patch", "")),
      fields_(dict.get<std::vector<std::string>>("fields")),
      reductions_(context.reductions) {
    if (fields_.empty()) dict.fail("fields", "lists no field");
    if (!patchName_.empty()) motion_ = patchByName(dict, "patch", patchName_, context.system).motion.get();
    for (const std::string& field : fields_) {
        checkInterpolatedField<D>(dict, "fields", field);
        std::string header = "# time";
        for (std::size_t k = 0; k < points_.size(); ++k) header += fmt::format(" {}({:g})", field, fmt::join(points_[k], " "));
        out_.push_back(context.series(field + ".dat", header));
    }
    if (const Dictionary* reference = dict.findSubDict("reference")) {
        if (fields_.size() != 1) dict.fail("fields", "a probes object with a reference compares one field; list one");
        std::vector<std::string> quantities;
        for (std::size_t k = 0; k < points_.size(); ++k) quantities.push_back(fmt::format("{} at probe {}", fields_[0], k));
        reference_.emplace(*reference, context.caseDirectory, quantities);
    }
}

template <int D>
std::string Probes<D>::describe() const {
    return fmt::format("probes: {} points, fields {}, {}{}", points_.size(), fmt::join(fields_, " "),
                       patchName_.empty() ? "in the lab frame" : "moving with patch " + patchName_, reference_ ? ", " + reference_->describe() : "");
}

template <int D>
std::vector<std::vector<double>> Probes<D>::sample(const FluidSystemView<D>& system, double t) const {
    std::vector<std::vector<double>> values(fields_.size(), std::vector<double>(points_.size()));
    std::vector<Vec<D>> at(points_);
    if (motion_)
        for (Vec<D>& point : at) point = motion_->at(point, Vec<D>::Unit(D - 1), t).position;
    const std::vector<InterpolatedFluid<D>> sampled = interpolateFluidAt(system, at, reductions_);
    for (std::size_t k = 0; k < points_.size(); ++k)
        for (std::size_t f = 0; f < fields_.size(); ++f) values[f][k] = fieldValue(sampled[k], fields_[f]);
    return values;
}

template <int D>
void Probes<D>::execute(const FluidSystemView<D>& system, double t) {
    const auto values = sample(system, t);
    for (std::size_t f = 0; f < fields_.size(); ++f) {
        std::string line = fmt::format("{:.9g}", t);
        for (const double value : values[f]) line += fmt::format(" {:.9g}", value);
        out_[f].append(line);
    }
    if (reference_) reference_->compare(t, values[0]);
}

template <int D>
std::vector<ReportedError> Probes<D>::errors() const {
    return errorsOf(reference_);
}

template class Probes<1>;
template class Probes<2>;
template class Probes<3>;

}  // namespace sph
