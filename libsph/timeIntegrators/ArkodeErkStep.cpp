#include "timeIntegrators/ArkodeErkStep.hpp"

#include "core/FatalError.hpp"

#include <arkode/arkode_butcher_erk.h>
#include <arkode/arkode_erkstep.h>
#include <fmt/format.h>

namespace sph {

template <int D>
std::vector<std::string> ArkodeErkStep<D>::tableNames() {
    // SUNDIALS 6.4's explicit tables (arkode_butcher_erk.h), in its order.
    return {"ARKODE_HEUN_EULER_2_1_2",     "ARKODE_BOGACKI_SHAMPINE_4_2_3", "ARKODE_ARK324L2SA_ERK_4_2_3", "ARKODE_ZONNEVELD_5_3_4",
            "ARKODE_ARK436L2SA_ERK_6_3_4", "ARKODE_SAYFY_ABURUB_6_3_4",     "ARKODE_CASH_KARP_6_4_5",      "ARKODE_FEHLBERG_6_4_5",
            "ARKODE_DORMAND_PRINCE_7_4_5", "ARKODE_ARK548L2SA_ERK_8_4_5",   "ARKODE_VERNER_8_5_6",         "ARKODE_FEHLBERG_13_7_8",
            "ARKODE_KNOTH_WOLKE_3_3",      "ARKODE_ARK437L2SA_ERK_7_3_4",   "ARKODE_ARK548L2SAb_ERK_8_4_5"};
}

template <int D>
ArkodeErkStep<D>::ArkodeErkStep(std::string table, AdaptivityOptions adaptivity)
    : SundialsIntegrator<D>("ARKODE ERKStep", false), table_(std::move(table)), adaptivity_(adaptivity) {}

template <int D>
ArkodeErkStep<D>::~ArkodeErkStep() {
    if (this->memory_) release();
}

template <int D>
std::string ArkodeErkStep<D>::describe() const {
    if (!adaptivity_.adaptive) return fmt::format("arkodeERK ({}, fixed step)", table_);
    return fmt::format("arkodeERK ({}, adaptive: relativeTolerance {:g}, absoluteTolerance {:g}, controller {})", table_,
                       adaptivity_.tolerances.relative, adaptivity_.tolerances.absolute, adaptivity_.controllerName);
}

template <int D>
int ArkodeErkStep<D>::rightHandSide(double t, N_Vector y, N_Vector ydot, void* self) {
    return static_cast<ArkodeErkStep<D>*>(self)->rates(t, y, ydot, RateTerms::All);
}

template <int D>
void ArkodeErkStep<D>::create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) {
    void*& memory = this->memory_;
    memory = ERKStepCreate(rightHandSide, t, y, this->state_.context());
    if (!memory) throw FatalError("error: could not create the ARKODE ERKStep integrator");
    ERKStepSetUserData(memory, this);
    ERKStepSetTableName(memory, table_.c_str());
    ERKStepSetMaxNumSteps(memory, -1);
    if (!adaptivity_.adaptive) return;
    ERKStepSVtolerances(memory, adaptivity_.tolerances.relative, this->state_.absoluteTolerances(system, adaptivity_.tolerances.absolute));
    ERKStepSetAdaptivityMethod(memory, adaptivity_.controller, 1, 0, nullptr);
    if (initialStep > 0.0) ERKStepSetInitStep(memory, initialStep);
}

template <int D>
bool ArkodeErkStep<D>::resize(IntegrableSystem<D>& system, double t, N_Vector y) {
    if (ERKStepResize(this->memory_, y, 1.0, t, nullptr, nullptr) != ARK_SUCCESS) return false;
    // The tolerances' vector is the old length: set again.
    if (adaptivity_.adaptive)
        ERKStepSVtolerances(this->memory_, adaptivity_.tolerances.relative, this->state_.absoluteTolerances(system, adaptivity_.tolerances.absolute));
    return true;
}

template <int D>
void ArkodeErkStep<D>::release() {
    ERKStepFree(&this->memory_);
}

template <int D>
int ArkodeErkStep<D>::advance(double t, double dt, double& reached) {
    if (!adaptivity_.adaptive) ERKStepSetFixedStep(this->memory_, dt);
    ERKStepSetStopTime(this->memory_, t + dt);
    return ERKStepEvolve(this->memory_, t + dt, this->state_.wrapped(), &reached, ARK_ONE_STEP);
}

template <int D>
std::string ArkodeErkStep<D>::flagName(int flag) const {
    return takeSundialsString(ERKStepGetReturnFlagName(flag));
}

template <int D>
double ArkodeErkStep<D>::nextStep() const {
    double step = 0.0;
    ERKStepGetCurrentStep(this->memory_, &step);
    return step;
}

template <int D>
void ArkodeErkStep<D>::addCounts(Counts& counts) const {
    long failures = 0;
    ERKStepGetNumErrTestFails(this->memory_, &failures);
    counts.rejected += failures;
}

template class ArkodeErkStep<1>;
template class ArkodeErkStep<2>;
template class ArkodeErkStep<3>;

}  // namespace sph
