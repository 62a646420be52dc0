#include "functionObjects/KernelInterpolation.hpp"

#include "physics/FluidSystemView.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace sph {

template <int D>
InterpolatedFluid<D> interpolateFluid(const FluidSystemView<D>& system, const Vec<D>& x) {
    const double* m = system.fluid[fields::mass].data();
    const double* rho = system.fluid[fields::density].data();
    const double* p = system.fluid[fields::pressure].data();
    const Vec<D>* v = system.fluid[fields::velocity].data();
    InterpolatedFluid<D> result;
    std::visit(
        [&](const auto& kernel) {
            system.fluidCells.forEachNeighbour(x, system.supportRadius, [&](std::uint32_t j, const Vec<D>&, double r2) {
                const double w = kernel.value(std::sqrt(r2)) * m[j] / rho[j];
                result.weight += w;
                result.pressure += w * p[j];
                result.density += w * rho[j];
                result.velocity += w * v[j];
            });
        },
        system.kernel);
    if (result.weight > 0.0) {
        const double inverse = 1.0 / result.weight;
        result.pressure *= inverse;
        result.density *= inverse;
        result.velocity *= inverse;
    }
    return result;
}

template <int D>
std::vector<InterpolatedFluid<D>> interpolateFluidAt(const FluidSystemView<D>& system, const std::vector<Vec<D>>& points,
                                                     const Reductions& reductions) {
    // Per point: weight, pressure, density, velocity. The others offer -infinity, so that the
    // largest is the answer as computed, to the bit and the sign of a zero.
    constexpr std::size_t record = 3 + D;
    std::vector<double> values(points.size() * record, -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (!system.answersFor(points[k])) continue;
        const InterpolatedFluid<D> sampled = interpolateFluid(system, points[k]);
        double* at = &values[k * record];
        at[0] = sampled.weight, at[1] = sampled.pressure, at[2] = sampled.density;
        for (int d = 0; d < D; ++d) at[3 + d] = sampled.velocity[d];
    }
    reductions.max(values);
    std::vector<InterpolatedFluid<D>> result(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        const double* at = &values[k * record];
        result[k].weight = at[0], result[k].pressure = at[1], result[k].density = at[2];
        for (int d = 0; d < D; ++d) result[k].velocity[d] = at[3 + d];
    }
    return result;
}

template <int D>
std::vector<Vec<D>> readSamplePoints(const Dictionary& dict, const std::string& keyword, const FluidSystemView<D>& system, const std::string& what) {
    const std::vector<Vec<D>> points = dict.getVectorList<D>(keyword);
    if (points.empty()) dict.fail(keyword, "lists no " + what);
    const Vec<D>& lo = system.domainMin;
    const Vec<D>& hi = system.domainMax;
    for (std::size_t k = 0; k < points.size(); ++k)
        if ((points[k].array() < lo.array()).any() || (points[k].array() > hi.array()).any())
            dict.fail(keyword, fmt::format("{} {} at ({:g}) lies outside the domain [({:g}), ({:g})]", what, k, fmt::join(points[k], " "),
                                           fmt::join(lo, " "), fmt::join(hi, " ")));
    return points;
}

template <int D>
double fieldValue(const InterpolatedFluid<D>& sample, const std::string& field) {
    if (field == "p") return sample.pressure;
    if (field == "rho") return sample.density;
    if (field == "U") return sample.velocity.norm();
    return sample.velocity[field == "Ux" ? 0 : field == "Uy" ? 1 : 2];
}

template <int D>
void checkInterpolatedField(const Dictionary& dict, const std::string& keyword, const std::string& field) {
    const bool valid = field == "p" || field == "rho" || field == "U" || field == "Ux" || (field == "Uy" && D >= 2) || (field == "Uz" && D >= 3);
    if (!valid)
        dict.fail(keyword,
                  fmt::format("unknown field '{}'; valid fields in {}D are: p, rho, U, Ux{}{}", field, D, D > 1 ? ", Uy" : "", D > 2 ? ", Uz" : ""));
}

template InterpolatedFluid<1> interpolateFluid<1>(const FluidSystemView<1>&, const Vec<1>&);
template std::vector<InterpolatedFluid<1>> interpolateFluidAt<1>(const FluidSystemView<1>&, const std::vector<Vec<1>>&, const Reductions&);
template InterpolatedFluid<2> interpolateFluid<2>(const FluidSystemView<2>&, const Vec<2>&);
template std::vector<InterpolatedFluid<2>> interpolateFluidAt<2>(const FluidSystemView<2>&, const std::vector<Vec<2>>&, const Reductions&);
template InterpolatedFluid<3> interpolateFluid<3>(const FluidSystemView<3>&, const Vec<3>&);
template std::vector<InterpolatedFluid<3>> interpolateFluidAt<3>(const FluidSystemView<3>&, const std::vector<Vec<3>>&, const Reductions&);
template double fieldValue<1>(const InterpolatedFluid<1>&, const std::string&);
template void checkInterpolatedField<1>(const Dictionary&, const std::string&, const std::string&);
template std::vector<Vec<1>> readSamplePoints<1>(const Dictionary&, const std::string&, const FluidSystemView<1>&, const std::string&);
template double fieldValue<2>(const InterpolatedFluid<2>&, const std::string&);
template void checkInterpolatedField<2>(const Dictionary&, const std::string&, const std::string&);
template std::vector<Vec<2>> readSamplePoints<2>(const Dictionary&, const std::string&, const FluidSystemView<2>&, const std::string&);
template double fieldValue<3>(const InterpolatedFluid<3>&, const std::string&);
template void checkInterpolatedField<3>(const Dictionary&, const std::string&, const std::string&);
template std::vector<Vec<3>> readSamplePoints<3>(const Dictionary&, const std::string&, const FluidSystemView<3>&, const std::string&);

}  // namespace sph
