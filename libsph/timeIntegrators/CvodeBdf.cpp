#include "timeIntegrators/CvodeBdf.hpp"

#include "core/FatalError.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <fmt/format.h>
#include <sunlinsol/sunlinsol_spgmr.h>

namespace sph {

template <int D>
CvodeBdf<D>::CvodeBdf(SundialsTolerances tolerances, int maxOrder, KrylovOptions krylov)
    : SundialsIntegrator<D>("CVODE", true), tolerances_(tolerances), maxOrder_(maxOrder), krylov_(krylov) {}

template <int D>
CvodeBdf<D>::~CvodeBdf() {
    if (this->memory_) release();
}

template <int D>
std::string CvodeBdf<D>::describe() const {
    return fmt::format("cvode (BDF up to order {}, relativeTolerance {:g}, absoluteTolerance {:g}; GMRES, maxKrylovDimension {})", maxOrder_,
                       tolerances_.relative, tolerances_.absolute, krylov_.maxKrylovDimension);
}

template <int D>
int CvodeBdf<D>::rightHandSide(double t, N_Vector y, N_Vector ydot, void* self) {
    return static_cast<CvodeBdf<D>*>(self)->rates(t, y, ydot, RateTerms::All);
}

template <int D>
void CvodeBdf<D>::create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) {
    void*& memory = this->memory_;
    memory = CVodeCreate(CV_BDF, this->state_.context());
    if (!memory || CVodeInit(memory, rightHandSide, t, y) != CV_SUCCESS) throw FatalError("error: could not create the CVODE integrator");
    CVodeSetUserData(memory, this);
    CVodeSVtolerances(memory, tolerances_.relative, this->state_.absoluteTolerances(system, tolerances_.absolute));
    CVodeSetMaxOrd(memory, maxOrder_);
    CVodeSetMaxNumSteps(memory, -1);
    linearSolver_ = SUNLinSol_SPGMR(y, SUN_PREC_NONE, krylov_.maxKrylovDimension, this->state_.context());
    CVodeSetLinearSolver(memory, linearSolver_, nullptr);
    if (initialStep > 0.0) CVodeSetInitStep(memory, initialStep);
}

template <int D>
void CvodeBdf<D>::release() {
    CVodeFree(&this->memory_);
    SUNLinSolFree(linearSolver_);
    linearSolver_ = nullptr;
}

template <int D>
int CvodeBdf<D>::advance(double t, double dt, double& reached) {
    CVodeSetStopTime(this->memory_, t + dt);
    return CVode(this->memory_, t + dt, this->state_.wrapped(), &reached, CV_ONE_STEP);
}

template <int D>
std::string CvodeBdf<D>::flagName(int flag) const {
    return takeSundialsString(CVodeGetReturnFlagName(flag));
}

template <int D>
double CvodeBdf<D>::nextStep() const {
    double step = 0.0;
    CVodeGetCurrentStep(this->memory_, &step);
    return step;
}

template <int D>
void CvodeBdf<D>::addCounts(Counts& counts) const {
    long value = 0;
    CVodeGetNumErrTestFails(this->memory_, &value), counts.rejected += value;
    CVodeGetNumNonlinSolvIters(this->memory_, &value), counts.nonlinearIterations += value;
    CVodeGetNumNonlinSolvConvFails(this->memory_, &value), counts.nonlinearFailures += value;
    CVodeGetNumLinIters(this->memory_, &value), counts.linearIterations += value;
}

template class CvodeBdf<1>;
template class CvodeBdf<2>;
template class CvodeBdf<3>;

}  // namespace sph
