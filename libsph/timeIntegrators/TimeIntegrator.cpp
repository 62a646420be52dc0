#include "timeIntegrators/TimeIntegrator.hpp"

#include "timeIntegrators/IntegrableSystem.hpp"
#include "timeIntegrators/ArkodeArkStepImex.hpp"
#include "timeIntegrators/ArkodeErkStep.hpp"
#include "timeIntegrators/CvodeBdf.hpp"
#include "timeIntegrators/LeapfrogKickDriftKick.hpp"
#include "timeIntegrators/PredictorCorrectorMonaghan1989.hpp"
#include "timeIntegrators/SymplecticPositionVerlet.hpp"
#include "timeIntegrators/VerletMonaghan1994.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sph {

template <int D>
void TimeIntegrator<D>::evaluate(IntegrableSystem<D>& system, double t) {
    evaluate(system, t, RateTerms::All);
}

template <int D>
void TimeIntegrator<D>::evaluate(IntegrableSystem<D>& system, double t, RateTerms terms) {
    ++evaluations_;
    system.evaluateRates(t, terms);
}

template <int D>
void TimeIntegrator<D>::evaluateAtStepEnd(IntegrableSystem<D>& system, double t) {
    system.evaluatingStepEnd = true;
    try {
        evaluate(system, t);
    } catch (...) {
        system.evaluatingStepEnd = false;
        throw;
    }
    system.evaluatingStepEnd = false;
}

template <int D>
std::vector<std::pair<std::string, long>> TimeIntegrator<D>::counters() const {
    return {{"steps", steps_}, {"right-hand-side evaluations", evaluations_}};
}

template <int D>
std::string TimeIntegrator<D>::countersReport() const {
    std::string report = "Integrator counters:\n";
    for (const auto& [name, value] : counters()) report += fmt::format("    {:<32} {}\n", name, value);
    return report;
}

template <int D>
void TimeIntegrator<D>::checkCompatible(const IntegrableSystem<D>& system, const Dictionary& dict) const {
    if (advancesFreeBodies()) return;
    for (const std::string& patch : system.freeBodyPatches())
        dict.fail("type", fmt::format("patch '{}' is a free body, which only the symplectic integrator advances; found {}", patch, describe()));
}

namespace {

std::string chooseName(const Dictionary& dict, const std::string& keyword, const std::string& fallback, const std::vector<std::string>& valid) {
    const std::string name = dict.getOrDefault<std::string>(keyword, fallback);
    if (std::find(valid.begin(), valid.end(), name) == valid.end())
        dict.fail(keyword, fmt::format("unknown {} '{}'; valid names are:\n    {}", keyword, name, fmt::join(valid, "\n    ")));
    return name;
}

}  // namespace

template <int D>
TimeIntegratorRegistry<D> makeTimeIntegratorRegistry() {
    using Pointer = std::unique_ptr<TimeIntegrator<D>>;
    TimeIntegratorRegistry<D> registry("time integrator");
    registry.add("symplectic",
                 {"symplectic position-Verlet predictor-corrector, 2 evaluations per step", "Dominguez et al., Comput. Phys. Commun. 262 (2021)", {}},
                 [](const Dictionary&) -> Pointer { return std::make_unique<SymplecticPositionVerlet<D>>(); });
    registry.add("verlet",
                 {"Verlet with an Euler step every eulerEvery steps, 1 evaluation per step",
                  "Monaghan, J. Comput. Phys. 110 (1994)",
                  {{"eulerEvery", "40", "steps between Euler steps (DualSPHysics' VerletSteps)"}}},
                 [](const Dictionary& dict) -> Pointer {
                     const int eulerEvery = dict.getOrDefault("eulerEvery", 40);
                     if (eulerEvery < 1) dict.fail("eulerEvery", fmt::format("must be at least 1, found {}", eulerEvery));
                     return std::make_unique<VerletMonaghan1994<D>>(eulerEvery);
                 });
    registry.add("leapfrog", {"kick-drift-kick leapfrog, 1 evaluation per step", "Springel, MNRAS 364 (2005)", {}},
                 [](const Dictionary&) -> Pointer { return std::make_unique<LeapfrogKickDriftKick<D>>(); });
    registry.add("predictorCorrector", {"predictor-corrector, 2 evaluations per step", "Monaghan, J. Comput. Phys. 82 (1989)", {}},
                 [](const Dictionary&) -> Pointer { return std::make_unique<PredictorCorrectorMonaghan1989<D>>(); });

    const std::vector<CoefficientDoc> adaptivityDocs{
        {"adaptive", "no", "yes: embedded error estimate sets the step (capped by the SPH step rules)"},
        {"relativeTolerance", "1e-4", "relative tolerance of the error test (adaptive) and, for arkodeIMEX, of the Newton test"},
        {"absoluteTolerance", "1e-6", "absolute tolerance, times h, c0, rho0 for positions, velocities, densities (as relativeTolerance)"},
        {"controller", "PID", "adaptivity controller: PID, PI, I, explicitGustafsson (IMEX adds implicitGustafsson, imexGustafsson)"}};
    auto erkDocs = adaptivityDocs;
    erkDocs.insert(erkDocs.begin(), {"table", "ARKODE_BOGACKI_SHAMPINE_4_2_3", "SUNDIALS name of an explicit Butcher table"});
    registry.add("arkodeERK", {"SUNDIALS ARKODE ERKStep, explicit Runge-Kutta", "Reynolds et al., ACM TOMS 49 (2023); SUNDIALS 6.4", erkDocs},
                 [](const Dictionary& dict) -> Pointer {
                     const std::string table = chooseName(dict, "table", "ARKODE_BOGACKI_SHAMPINE_4_2_3", ArkodeErkStep<D>::tableNames());
                     return std::make_unique<ArkodeErkStep<D>>(table, readAdaptivity(dict, {"PID", "PI", "I", "explicitGustafsson"}));
                 });
    auto imexDocs = adaptivityDocs;
    imexDocs.insert(imexDocs.begin(), {"table", "ARK324L2SA", "ARKODE IMEX pair: ARK324L2SA, ARK436L2SA, ARK437L2SA, ARK548L2SA, ARK548L2SAb"});
    const std::vector<CoefficientDoc> krylovDocs{
        {"maxKrylovDimension", "10", "GMRES subspace size"},
        {"jacobianTimesVector", "differenceQuotient", "differenceQuotient, or velocityBlock (analytic, laminar viscosity)"}};
    imexDocs.insert(imexDocs.end(), krylovDocs.begin(), krylovDocs.end());
    registry.add("arkodeIMEX",
                 {"SUNDIALS ARKODE ARKStep IMEX: viscosity implicit (Newton-GMRES), the rest explicit",
                  "Kennedy & Carpenter, Appl. Numer. Math. 44 (2003); SUNDIALS 6.4", imexDocs},
                 [](const Dictionary& dict) -> Pointer {
                     const std::string table = chooseName(dict, "table", "ARK324L2SA", ArkodeArkStepImex<D>::tableNames());
                     auto adaptivity = readAdaptivity(dict, {"PID", "PI", "I", "explicitGustafsson", "implicitGustafsson", "imexGustafsson"});
                     if (!adaptivity.adaptive) adaptivity.tolerances = readTolerances(dict);  // the Newton convergence test
                     return std::make_unique<ArkodeArkStepImex<D>>(table, adaptivity, readKrylovOptions(dict));
                 });
    std::vector<CoefficientDoc> cvodeDocs{{"relativeTolerance", "1e-4", "relative tolerance"},
                                          {"absoluteTolerance", "1e-6", "absolute tolerance, times h, c0, rho0 for positions, velocities, densities"},
                                          {"maxOrder", "5", "highest BDF order (1 to 5)"},
                                          krylovDocs.front()};
    registry.add("cvode", {"SUNDIALS CVODE BDF, fully implicit (Newton-GMRES)", "Hindmarsh et al., ACM TOMS 31 (2005); SUNDIALS 6.4", cvodeDocs},
                 [](const Dictionary& dict) -> Pointer {
                     const int maxOrder = dict.getOrDefault("maxOrder", 5);
                     if (maxOrder < 1 || maxOrder > 5) dict.fail("maxOrder", fmt::format("must be 1 to 5, found {}", maxOrder));
                     KrylovOptions krylov;
                     krylov.maxKrylovDimension = readMaxKrylovDimension(dict);
                     return std::make_unique<CvodeBdf<D>>(readTolerances(dict), maxOrder, krylov);
                 });
    return registry;
}

template class TimeIntegrator<1>;
template class TimeIntegrator<2>;
template class TimeIntegrator<3>;
template TimeIntegratorRegistry<1> makeTimeIntegratorRegistry<1>();
template TimeIntegratorRegistry<2> makeTimeIntegratorRegistry<2>();
template TimeIntegratorRegistry<3> makeTimeIntegratorRegistry<3>();

}  // namespace sph
