#include "timeIntegrators/SundialsState.hpp"

#include "core/FatalError.hpp"
#include "timeIntegrators/EvolvedState.hpp"
#include "timeIntegrators/StateOverRanks.hpp"

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
std::size_t SundialsState<D>::Block::length() const {
    const std::size_t particles = owned ? static_cast<std::size_t>(std::count(owned->begin(), owned->end(), 1)) : held;
    return particles * width;
}

template <int D>
std::vector<typename SundialsState<D>::Block> SundialsState<D>::blocks(IntegrableSystem<D>& system, Values values) const {
    static_assert(sizeof(Vec<D>) == D * sizeof(double), "particle vectors must be packed doubles to be wrapped");
    const StateOverRanks* ranks = system.stateOverRanks;
    const std::vector<char>* fluidOwned = ranks ? ranks->fluidOwned : nullptr;
    const std::size_t n = system.fluid.ownedCount();
    const bool rates = values == Values::Rates;
    std::vector<Block> result{{system.fluid.position.data()->data(), D, n, fluidOwned},
                              {system.fluid[rates ? fields::acceleration : fields::velocity].data()->data(), D, n, fluidOwned}};
    for (ParticleSet<D>* set : evolvedDensitySets(system))
        result.push_back({(*set)[rates ? fields::densityRate : fields::density].data(), 1, set->ownedCount(),
                          ranks ? (set == &system.fluid ? ranks->fluidOwned : ranks->wallsOwned) : nullptr});
    return result;
}

namespace {

// A block's values of the particles the vector holds, in their order, to `to`; and back.
template <class Block>
void gather(const Block& block, double* to) {
    for (std::size_t i = 0; i < block.held; ++i)
        if (!block.owned || (*block.owned)[i]) to = std::copy_n(block.data + i * block.width, block.width, to);
}

template <class Block>
void scatter(const double* from, const Block& block) {
    for (std::size_t i = 0; i < block.held; ++i)
        if (!block.owned || (*block.owned)[i]) {
            std::copy_n(from, block.width, block.data + i * block.width);
            from += block.width;
        }
}

}  // namespace

template <int D>
N_Vector SundialsState<D>::wrap(IntegrableSystem<D>& system) {
    if (wrapped_) N_VDestroy(wrapped_);
    for (N_Vector part : parts_) N_VDestroy(part);
    parts_.clear();
    const StateOverRanks* ranks = system.stateOverRanks;
    for (const Block& block : blocks(system)) {
        const auto length = static_cast<sunindextype>(block.length());
        if (!block.owned) {
            parts_.push_back(N_VMake_Serial(length, block.data, context_));
            continue;
        }
        parts_.push_back(N_VNew_Serial(length, context_));
        gather(block, N_VGetArrayPointer(parts_.back()));
    }
    subvectorData_ = ranks ? ranks->subvectorData : N_VGetSubvectorArrayPointer_ManyVector;
    wrapped_ = ranks ? ranks->join(parts_, context_) : N_VNew_ManyVector(static_cast<sunindextype>(parts_.size()), parts_.data(), context_);
    evaluatedValid_ = false;
    return wrapped_;
}

template <int D>
N_Vector SundialsState<D>::absoluteTolerances(const IntegrableSystem<D>& system, double absolute) {
    if (absoluteTolerances_) N_VDestroy(absoluteTolerances_);
    absoluteTolerances_ = N_VClone(wrapped_);
    const StateScales scales = system.scales();
    for (std::size_t k = 0; k < parts_.size(); ++k) {
        const double scale = k == 0 ? scales.smoothingLength : k == 1 ? scales.speedOfSound : scales.referenceDensity;
        std::fill_n(part(absoluteTolerances_, k), N_VGetLength(parts_[k]), absolute * scale);
    }
    return absoluteTolerances_;
}

template <int D>
void SundialsState<D>::markEvaluated(IntegrableSystem<D>& system, double t) {
    evaluatedState_.clear();
    for (const Block& block : blocks(system)) {
        const std::size_t offset = evaluatedState_.size();
        evaluatedState_.resize(offset + block.length());
        gather(block, evaluatedState_.data() + offset);
    }
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
        const std::size_t size = parts[k].length();
        if (offset + size > evaluatedState_.size()) return false;
        if (size > 0 && std::memcmp(part(y, k), evaluatedState_.data() + offset, size * sizeof(double)) != 0) return false;
        offset += size;
    }
    return offset == evaluatedState_.size();
}

template <int D>
void SundialsState<D>::load(IntegrableSystem<D>& system, N_Vector y) {
    const auto parts = blocks(system);
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const double* data = part(y, k);
        if (parts[k].owned)
            scatter(data, parts[k]);
        else if (data != parts[k].data)
            std::memcpy(parts[k].data, data, parts[k].length() * sizeof(double));
    }
    if (system.stateOverRanks) system.stateOverRanks->refreshCopies();
    evaluatedValid_ = false;
}

template <int D>
void SundialsState<D>::evaluateAtStepEnd(IntegrableSystem<D>& system, double t, const std::function<void(double, RateTerms)>& evaluate) {
    bool current = evaluatedValid_ && t == evaluatedTime_ && isEvaluatedState(system, wrapped_);
    if (system.stateOverRanks) current = !system.stateOverRanks->onAnyRank(!current);
    if (current) return;
    load(system, wrapped_);
    evaluate(t, RateTerms::All);
    markEvaluated(system, t);
}

template <int D>
std::string SundialsState<D>::storeRates(IntegrableSystem<D>& system, double t, N_Vector y, N_Vector ydot, bool viscousOnly) {
    const auto state = blocks(system);
    const auto rateBlocks = blocks(system, Values::Rates);
    const std::size_t positions = state[0].length();
    if (viscousOnly)
        std::fill_n(part(ydot, 0), positions, 0.0);
    else
        std::copy_n(part(y, 1), positions, part(ydot, 0));
    for (std::size_t k = 1; k < rateBlocks.size(); ++k) {
        double* rate = part(ydot, k);
        gather(rateBlocks[k], rate);
        const auto bad = std::find_if(rate, rate + rateBlocks[k].length(), [](double value) { return !std::isfinite(value); });
        if (bad != rate + rateBlocks[k].length()) {
            // The particle: the (bad - rate) / width-th of those the vector holds.
            const ParticleSet<D>& set = k < 2 ? system.fluid : *evolvedDensitySets(system)[k - 2];
            std::size_t wanted = static_cast<std::size_t>(bad - rate) / rateBlocks[k].width, i = 0;
            for (;; ++i)
                if (!rateBlocks[k].owned || (*rateBlocks[k].owned)[i])
                    if (wanted-- == 0) break;
            if (k == 1)
                return fmt::format("fluid particle id {} at ({:g}) has a non-finite acceleration at time {:.9g}", set.globalId[i],
                                   fmt::join(set.position[i], " "), t);
            return fmt::format("{} particle id {} has a non-finite density rate at time {:.9g}", set.name(), set.globalId[i], t);
        }
        if (viscousOnly && k > 1) std::fill_n(rate, rateBlocks[k].length(), 0.0);
    }
    return {};
}

template <int D>
int SundialsState<D>::rates(IntegrableSystem<D>& system, double t, N_Vector y, N_Vector ydot, RateTerms terms,
                            const std::function<void(double, RateTerms)>& evaluate) {
    const StateOverRanks* ranks = system.stateOverRanks;
    bool cached = terms == RateTerms::All && evaluatedValid_ && t == evaluatedTime_ && isEvaluatedState(system, y);
    if (ranks) cached = !ranks->onAnyRank(!cached);
    std::string failure;
    try {
        if (!cached) {
            {
                auto timer = system.timers.time(Stage::Integrator);
                load(system, y);
            }
            evaluate(t, terms);
            if (terms == RateTerms::All) markEvaluated(system, t);
        }
        auto timer = system.timers.time(Stage::Integrator);
        failure = storeRates(system, t, y, ydot, terms == RateTerms::ViscousOnly);
    } catch (const std::exception& error) {
        if (ranks) ranks->stopAll(error.what());
        failure = error.what();
    }
    if (ranks && ranks->onAnyRank(!failure.empty()) && failure.empty()) failure = "an evaluation failed on another rank";
    if (failure.empty()) return 0;
    lastFailure_ = failure;
    evaluatedValid_ = false;
    return 1;
}

template <int D>
int SundialsState<D>::viscousJacobianTimes(IntegrableSystem<D>& system, double t, N_Vector w, N_Vector Jw, N_Vector y, N_Vector fy,
                                           const std::function<void(double, RateTerms)>& evaluate) {
    const StateOverRanks* ranks = system.stateOverRanks;
    try {
        load(system, y);
        auto& v = system.fluid[fields::velocity];
        const std::vector<Vec<D>> velocity = v;  // y may be the wrapped arrays themselves
        // v + w: w in the velocity block's place of the vector, added to the particles it holds.
        Block perturbed = blocks(system)[1];
        std::vector<double> sum(perturbed.length());
        gather(perturbed, sum.data());
        const double* wv = part(w, 1);
        for (std::size_t j = 0; j < sum.size(); ++j) sum[j] += wv[j];
        scatter(sum.data(), perturbed);
        if (ranks) ranks->refreshCopies();
        evaluate(t, RateTerms::ViscousOnly);
        v = velocity;  // the copies' too
        N_VConst(0.0, Jw);
        double* Jv = part(Jw, 1);
        gather(blocks(system, Values::Rates)[1], Jv);
        const double* av = part(fy, 1);
        for (std::size_t j = 0; j < sum.size(); ++j) Jv[j] -= av[j];
        return 0;
    } catch (const std::exception& error) {
        if (ranks) ranks->stopAll(error.what());
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
