#include "timeIntegrators/ArkodeArkStepImex.hpp"

#include "core/FatalError.hpp"

#include <arkode/arkode_arkstep.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <map>

namespace sph {

namespace {

// ARKODE's IMEX pairs: name -> the suffix (stages, order, embedded order) of both tables.
const std::map<std::string, std::string>& imexPairs() {
    static const std::map<std::string, std::string> pairs{
        {"ARK324L2SA", "4_2_3"}, {"ARK436L2SA", "6_3_4"}, {"ARK437L2SA", "7_3_4"}, {"ARK548L2SA", "8_4_5"}, {"ARK548L2SAb", "8_4_5"}};
    return pairs;
}

}  // namespace

template <int D>
std::vector<std::string> ArkodeArkStepImex<D>::tableNames() {
    std::vector<std::string> names;
    for (const auto& [name, suffix] : imexPairs()) names.push_back(name);
    return names;
}

template <int D>
ArkodeArkStepImex<D>::ArkodeArkStepImex(std::string table, AdaptivityOptions adaptivity, KrylovOptions krylov)
    : SundialsIntegrator<D>("ARKODE ARKStep", true), table_(std::move(table)), adaptivity_(adaptivity), krylov_(krylov) {}

template <int D>
ArkodeArkStepImex<D>::~ArkodeArkStepImex() {
    if (this->memory_) release();
}

template <int D>
std::string ArkodeArkStepImex<D>::describe() const {
    const std::string jacobian = krylov_.jacobian == JacobianTimesVector::VelocityBlock ? "velocityBlock" : "differenceQuotient";
    const std::string stepping = adaptivity_.adaptive ? "adaptive, controller " + adaptivity_.controllerName : "fixed step";
    return fmt::format(
        "arkodeIMEX ({}, {}, relativeTolerance {:g}, absoluteTolerance {:g}; GMRES, maxKrylovDimension {}, "
        "jacobianTimesVector {}; viscosity implicit)",
        table_, stepping, adaptivity_.tolerances.relative, adaptivity_.tolerances.absolute, krylov_.maxKrylovDimension, jacobian);
}

template <int D>
void ArkodeArkStepImex<D>::checkCompatible(const IntegrableSystem<D>& system, const Dictionary& dict) const {
    TimeIntegrator<D>::checkCompatible(system, dict);
    if (krylov_.jacobian == JacobianTimesVector::VelocityBlock && !std::holds_alternative<LaminarViscosityMorris1997>(system.viscosity()))
        dict.fail("jacobianTimesVector", "velocityBlock is exact only for a viscosity linear in velocity (laminar); the case selects " +
                                             sph::describe(system.viscosity()) + "; use differenceQuotient");
    for (const std::string& patch : system.patchesWithWallViscousStress())
        dict.fail("type", "arkodeIMEX takes the fluid's viscosity implicitly, but wall patch '" + patch +
                              "' adds its laminar stress among the wall forces (the deficiency correction's noSlip), which it would take "
                              "explicitly, beyond their stable step; use an explicit integrator or cvode, or noSlip no on that patch");
}

template <int D>
int ArkodeArkStepImex<D>::explicitPart(double t, N_Vector y, N_Vector ydot, void* self) {
    return static_cast<ArkodeArkStepImex<D>*>(self)->rates(t, y, ydot, RateTerms::AllButViscous);
}

template <int D>
int ArkodeArkStepImex<D>::implicitPart(double t, N_Vector y, N_Vector ydot, void* self) {
    return static_cast<ArkodeArkStepImex<D>*>(self)->rates(t, y, ydot, RateTerms::ViscousOnly);
}

template <int D>
int ArkodeArkStepImex<D>::jacobianTimes(N_Vector w, N_Vector Jw, double t, N_Vector y, N_Vector fy, void* self, N_Vector) {
    return static_cast<ArkodeArkStepImex<D>*>(self)->viscousJacobianTimes(t, w, Jw, y, fy);
}

template <int D>
void ArkodeArkStepImex<D>::create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) {
    void*& memory = this->memory_;
    memory = ARKStepCreate(explicitPart, implicitPart, t, y, this->state_.context());
    if (!memory) throw FatalError("error: could not create the ARKODE ARKStep integrator");
    ARKStepSetUserData(memory, this);
    const std::string& suffix = imexPairs().at(table_);
    ARKStepSetTableName(memory, ("ARKODE_" + table_ + "_DIRK_" + suffix).c_str(), ("ARKODE_" + table_ + "_ERK_" + suffix).c_str());
    ARKStepSetMaxNumSteps(memory, -1);
    linearSolver_ = SUNLinSol_SPGMR(y, SUN_PREC_NONE, krylov_.maxKrylovDimension, this->state_.context());
    ARKStepSetLinearSolver(memory, linearSolver_, nullptr);
    if (krylov_.jacobian == JacobianTimesVector::VelocityBlock) ARKStepSetJacTimes(memory, nullptr, jacobianTimes);
    ARKStepSVtolerances(memory, adaptivity_.tolerances.relative, this->state_.absoluteTolerances(system, adaptivity_.tolerances.absolute));
    if (!adaptivity_.adaptive) return;
    ARKStepSetAdaptivityMethod(memory, adaptivity_.controller, 1, 0, nullptr);
    if (initialStep > 0.0) ARKStepSetInitStep(memory, initialStep);
}

template <int D>
void ArkodeArkStepImex<D>::release() {
    ARKStepFree(&this->memory_);
    SUNLinSolFree(linearSolver_);
    linearSolver_ = nullptr;
}

template <int D>
int ArkodeArkStepImex<D>::advance(double t, double dt, double& reached) {
    if (!adaptivity_.adaptive) ARKStepSetFixedStep(this->memory_, dt);
    ARKStepSetStopTime(this->memory_, t + dt);
    return ARKStepEvolve(this->memory_, t + dt, this->state_.wrapped(), &reached, ARK_ONE_STEP);
}

template <int D>
std::string ArkodeArkStepImex<D>::flagName(int flag) const {
    return takeSundialsString(ARKStepGetReturnFlagName(flag));
}

template <int D>
double ArkodeArkStepImex<D>::nextStep() const {
    double step = 0.0;
    ARKStepGetCurrentStep(this->memory_, &step);
    return step;
}

template <int D>
void ArkodeArkStepImex<D>::addCounts(Counts& counts) const {
    long value = 0;
    ARKStepGetNumErrTestFails(this->memory_, &value), counts.rejected += value;
    ARKStepGetNumNonlinSolvIters(this->memory_, &value), counts.nonlinearIterations += value;
    ARKStepGetNumNonlinSolvConvFails(this->memory_, &value), counts.nonlinearFailures += value;
    ARKStepGetNumLinIters(this->memory_, &value), counts.linearIterations += value;
}

template class ArkodeArkStepImex<1>;
template class ArkodeArkStepImex<2>;
template class ArkodeArkStepImex<3>;

}  // namespace sph
