// SUNDIALS ARKODE ARKStep, implicit-explicit additive Runge-Kutta: the viscous acceleration is
// implicit, everything else (pressure, gravity, density rates, boundary forces) explicit.
// Each implicit stage is solved by Newton's method with SUNDIALS' matrix-free GMRES; the
// Jacobian-vector product is SUNDIALS' difference quotient, or `velocityBlock`: the viscous
// operator applied to the velocity part of the vector with positions and densities frozen,
// exact for laminar (Morris) viscosity, which is linear in velocity. The explicit viscous
// step limit 0.125 h^2/nu no longer applies; the acoustic and force limits do.
// Tables by the name of ARKODE's IMEX pairs (ARK324L2SA, ARK436L2SA, ARK437L2SA, ARK548L2SA,
// ARK548L2SAb); fixed step or adaptive as for arkodeERK (controllers add implicitGustafsson,
// imexGustafsson). The tolerances set the Newton iteration's convergence test in both modes.
// Reference: C.A. Kennedy, M.H. Carpenter, Appl. Numer. Math. 44 (2003) 139-181; SUNDIALS 6.4
// user guide (ARKStep, SPGMR).
// Example (system/timeIntegration):
//   integrator { type arkodeIMEX; table ARK324L2SA; adaptive no; relativeTolerance 1e-4;
//                absoluteTolerance 1e-6; jacobianTimesVector velocityBlock; maxKrylovDimension 10; }
#pragma once

#include "timeIntegrators/SundialsIntegrator.hpp"

namespace sph {

template <int D>
class ArkodeArkStepImex : public SundialsIntegrator<D> {
public:
    ArkodeArkStepImex(std::string table, AdaptivityOptions adaptivity, KrylovOptions krylov);
    ~ArkodeArkStepImex() override;
    std::string describe() const override;
    bool viscosityImplicit() const override { return true; }
    void checkCompatible(const IntegrableSystem<D>& system, const Dictionary& dict) const override;

    static std::vector<std::string> tableNames();

protected:
    using typename SundialsIntegrator<D>::Counts;
    void create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) override;
    void release() override;
    int advance(double t, double dt, double& reached) override;
    std::string flagName(int flag) const override;
    double nextStep() const override;
    void addCounts(Counts& counts) const override;

private:
    static int explicitPart(double t, N_Vector y, N_Vector ydot, void* self);
    static int implicitPart(double t, N_Vector y, N_Vector ydot, void* self);
    static int jacobianTimes(N_Vector w, N_Vector Jw, double t, N_Vector y, N_Vector fy, void* self, N_Vector work);

    std::string table_;
    AdaptivityOptions adaptivity_;
    KrylovOptions krylov_;
    SUNLinearSolver linearSolver_ = nullptr;
};

}  // namespace sph
