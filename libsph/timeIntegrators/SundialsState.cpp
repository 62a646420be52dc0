#include "timeIntegrators/SundialsState.hpp"

#include "core/FatalError.hpp"
#include "timeIntegrators/EvolvedState.hpp"

#include <fmt/format.h>
#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace sph {

SundialsTolerances readTolerances(const Dictionary& dict) {
    SundialsTolerances tolerances;
    tolerances.relative = dict.getPositiveOrDefault("relativeTolerance", tolerances.relative);
    tolerances.absolute = dict.getPositiveOrDefault("absoluteTolerance", tolerances.absolute);
    return tolerances;
}

AdaptivityOptions readAdaptivity(const Dictionary& dict, const std::vector<std::string>& controllers) {
    AdaptivityOptions options;
    options.adaptive = dict.getOrDefault("adaptive", false);
    if (!options.adaptive) return options;
    options.tolerances = readTolerances(dict);
    options.controllerName = dict.getOrDefault<std::string>("controller", options.controllerName);
    static const std::vector<std::string> methods{"PID", "PI", "I", "explicitGustafsson", "implicitGustafsson", "imexGustafsson"};
    const auto valid = std::find(controllers.begin(), controllers.end(), options.controllerName);
    if (valid == controllers.end())
        dict.fail("controller", fmt::format("unknown adaptivity controller '{}'; valid controller names are:\n    {}", options.controllerName,
                                            fmt::join(controllers, "\n    ")));
    options.controller = static_cast<int>(std::find(methods.begin(), methods.end(), options.controllerName) - methods.begin());
    return options;
}

int readMaxKrylovDimension(const Dictionary& dict) {
    const int dimension = dict.getOrDefault("maxKrylovDimension", 10);
    if (dimension < 1) dict.fail("maxKrylovDimension", fmt::format("must be at least 1, found {}", dimension));
    return dimension;
}

KrylovOptions readKrylovOptions(const Dictionary& dict) {
    KrylovOptions options;
    options.maxKrylovDimension = readMaxKrylovDimension(dict);
    const std::string jacobian = dict.getOrDefault<std::string>("jacobianTimesVector", "differenceQuotient");
    if (jacobian == "velocityBlock")
        options.jacobian = JacobianTimesVector::VelocityBlock;
    else if (jacobian != "differenceQuotient")
        dict.fail("jacobianTimesVector",
                  "unknown Jacobian-vector product '" + jacobian + "'; valid names are:\n    differenceQuotient\n    velocityBlock");
    return options;
}

template <int D>
SundialsState<D>::SundialsState() {
    if (SUNContext_Create(nullptr, &context_) != 0) throw FatalError("error: could not create the SUNDIALS context");
}

template <int D>
SundialsState<D>::~SundialsState() {
    if (absoluteTolerances_) N_VDestroy(absoluteTolerances_);
    if (wrapped_) N_VDestroy(wrapped_);
    for (N_Vector part : parts_) N_VDestroy(part);
    SUNContext_Free(&context_);
}

template <int D>
std::vector<std::pair<double*, std::size_t>> SundialsState<D>::blocks(IntegrableSystem<D>& system) const {
    static_assert(sizeof(Vec<D>) == D * sizeof(double), "particle vectors must be packed doubles to be wrapped");
    const std::size_t n = system.fluid.ownedCount();
    std::vector<std::pair<double*, std::size_t>> result{{system.fluid.position.data()->data(), n * D},
                                                        {system.fluid[fields::velocity].data()->data(), n * D}};
    for (ParticleSet<D>* set : evolvedDensitySets(system)) result.emplace_back((*set)[fields::density].data(), set->ownedCount());
    return result;
}

template <int D>
N_Vector SundialsState<D>::wrap(IntegrableSystem<D>& system) {
    if (wrapped_) N_VDestroy(wrapped_);
    for (N_Vector part : parts_) N_VDestroy(part);
    parts_.clear();
    for (const auto& [data, size] : blocks(system)) parts_.push_back(N_VMake_Serial(static_cast<sunindextype>(size), data, context_));
    wrapped_ = N_VNew_ManyVector(static_cast<sunindextype>(parts_.size()), parts_.data(), context_);
    evaluatedValid_ = false;
    return wrapped_;
}

template <int D>
N_Vector SundialsState<D>::absoluteTolerances(const IntegrableSystem<D>& system, double absolute) {
    if (absoluteTolerances_) N_VDestroy(absoluteTolerances_);
    absoluteTolerances_ = N_VClone(wrapped_);
    const StateScales scales = system.scales();
    for (sunindextype k = 0; k < N_VGetNumSubvectors_ManyVector(absoluteTolerances_); ++k) {
        const double scale = k == 0 ? scales.smoothingLength : k == 1 ? scales.speedOfSound : scales.referenceDensity;
        N_VConst(absolute * scale, N_VGetSubvector_ManyVector(absoluteTolerances_, k));
    }
    return absoluteTolerances_;
}

template <int D>
void SundialsState<D>::markEvaluated(IntegrableSystem<D>& system, double t) {
    evaluatedState_.clear();
    for (const auto& [data, size] : blocks(system)) evaluatedState_.insert(evaluatedState_.end(), data, data + size);
    evaluatedTime_ = t;
    evaluatedValid_ = true;
}

// y against the copy, not against the system's arrays: in ARK_ONE_STEP mode ARKODE computes its
// stages in the output vector, which wraps those arrays, so y may be those arrays and still not
// the state the rates were evaluated at (a second stage at the same time, a FSAL stage).
template <int D>
bool SundialsState<D>::isEvaluatedState(IntegrableSystem<D>& system, N_Vector y) const {
    std::size_t offset = 0;
    const auto parts = blocks(system);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const std::size_t size = parts[k].second;
        if (offset + size > evaluatedState_.size()) return false;
        const double* data = N_VGetSubvectorArrayPointer_ManyVector(y, static_cast<sunindextype>(k));
        if (std::memcmp(data, evaluatedState_.data() + offset, size * sizeof(double)) != 0) return false;
        offset += size;
    }
    return offset == evaluatedState_.size();
}

template <int D>
void SundialsState<D>::load(IntegrableSystem<D>& system, N_Vector y) {
    const auto parts = blocks(system);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const double* data = N_VGetSubvectorArrayPointer_ManyVector(y, static_cast<sunindextype>(k));
        if (data != parts[k].first) std::memcpy(parts[k].first, data, parts[k].second * sizeof(double));
    }
    evaluatedValid_ = false;
}

template <int D>
int SundialsState<D>::rates(IntegrableSystem<D>& system, double t, N_Vector y, N_Vector ydot, RateTerms terms,
                            const std::function<void(double, RateTerms)>& evaluate) {
    try {
        const bool cached = terms == RateTerms::All && evaluatedValid_ && t == evaluatedTime_ && isEvaluatedState(system, y);
        if (!cached) {
            auto timer = system.timers.time(Stage::Integrator);
            load(system, y);
        }
        if (!cached) evaluate(t, terms);
        if (terms == RateTerms::All && !cached) markEvaluated(system, t);
        auto timer = system.timers.time(Stage::Integrator);
        const std::size_t n = system.fluid.ownedCount();
        const bool viscousOnly = terms == RateTerms::ViscousOnly;
        double* positionRate = N_VGetSubvectorArrayPointer_ManyVector(ydot, 0);
        if (viscousOnly)
            std::fill(positionRate, positionRate + n * D, 0.0);
        else
            std::memcpy(positionRate, N_VGetSubvectorArrayPointer_ManyVector(y, 1), n * D * sizeof(double));
        const auto& a = system.fluid[fields::acceleration];
        double* velocityRate = N_VGetSubvectorArrayPointer_ManyVector(ydot, 1);
        for (std::size_t i = 0; i < n; ++i) {
            if (!a[i].allFinite())
                throw std::runtime_error(fmt::format("fluid particle id {} at ({:g}) has a non-finite acceleration at time {:.9g}",
                                                     system.fluid.globalId[i], fmt::join(system.fluid.position[i], " "), t));
            for (int d = 0; d < D; ++d) velocityRate[i * D + d] = a[i][d];
        }
        sunindextype k = 2;
        for (ParticleSet<D>* set : evolvedDensitySets(system)) {
            const auto& rate = (*set)[fields::densityRate];
            double* densityRate = N_VGetSubvectorArrayPointer_ManyVector(ydot, k++);
            for (std::size_t i = 0; i < set->ownedCount(); ++i) {
                if (!std::isfinite(rate[i]))
                    throw std::runtime_error(
                        fmt::format("{} particle id {} has a non-finite density rate at time {:.9g}", set->name(), set->globalId[i], t));
                densityRate[i] = viscousOnly ? 0.0 : rate[i];
            }
        }
        return 0;
    } catch (const std::exception& error) {
        lastFailure_ = error.what();
        evaluatedValid_ = false;
        return 1;
    }
}

template <int D>
int SundialsState<D>::viscousJacobianTimes(IntegrableSystem<D>& system, double t, N_Vector w, N_Vector Jw, N_Vector y, N_Vector fy,
                                           const std::function<void(double, RateTerms)>& evaluate) {
    try {
        load(system, y);
        const std::size_t n = system.fluid.ownedCount();
        auto& v = system.fluid[fields::velocity];
        const std::vector<Vec<D>> velocity = v;  // y may be the wrapped arrays themselves
        const double* wv = N_VGetSubvectorArrayPointer_ManyVector(w, 1);
        for (std::size_t i = 0; i < n; ++i)
            for (int d = 0; d < D; ++d) v[i][d] += wv[i * D + d];
        evaluate(t, RateTerms::ViscousOnly);
        v = velocity;
        N_VConst(0.0, Jw);
        const auto& a = system.fluid[fields::acceleration];
        const double* av = N_VGetSubvectorArrayPointer_ManyVector(fy, 1);
        double* Jv = N_VGetSubvectorArrayPointer_ManyVector(Jw, 1);
        for (std::size_t i = 0; i < n; ++i)
            for (int d = 0; d < D; ++d) Jv[i * D + d] = a[i][d] - av[i * D + d];
        return 0;
    } catch (const std::exception& error) {
        lastFailure_ = error.what();
        return 1;
    }
}

std::string takeSundialsString(char* allocated) {
    std::string result = allocated ? allocated : "(unnamed flag)";
    std::free(allocated);
    return result;
}

void failIntegration(const std::string& solver, const std::string& flagName, double t, const std::string& rightHandSideFailure) {
    std::string message = fmt::format("error: the run blew up at time {:.9g}: {} stopped with {}", t, solver, flagName);
    if (!rightHandSideFailure.empty()) message += "\n    last right-hand-side failure: " + rightHandSideFailure;
    message += "\n    The last written time is kept; reduce the time step (courant) or tighten the tolerances.";
    throw FatalError(message);
}

template class SundialsState<1>;
template class SundialsState<2>;
template class SundialsState<3>;

}  // namespace sph
