// SUNDIALS ARKODE ERKStep: explicit Runge-Kutta methods from ARKODE's Butcher tables, by name.
// Fixed step (the SPH step rules give dt), or adaptive: the embedded error estimate with
// relative and absolute tolerances sets the step, never above the step rules', with the
// adaptivity controller chosen by name (PID, PI, I, explicitGustafsson).
// The absolute tolerance is scaled by h for positions, c0 for velocities, rho0 for densities.
// Reference: D.R. Reynolds et al., ARKODE, ACM Trans. Math. Softw. 49 (2023); SUNDIALS 6.4
// user guide (ERKStep, Butcher tables, adaptivity).
// Example (system/timeIntegration):
//   integrator { type arkodeERK; table ARKODE_BOGACKI_SHAMPINE_4_2_3; adaptive yes;
//                relativeTolerance 1e-4; absoluteTolerance 1e-6; controller PID; }
#pragma once

#include "timeIntegrators/SundialsIntegrator.hpp"

namespace sph {

template <int D>
class ArkodeErkStep : public SundialsIntegrator<D> {
public:
    ArkodeErkStep(std::string table, AdaptivityOptions adaptivity);
    ~ArkodeErkStep() override;
    std::string describe() const override;

    static std::vector<std::string> tableNames();

protected:
    using typename SundialsIntegrator<D>::Counts;
    void create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) override;
    bool resize(IntegrableSystem<D>& system, double t, N_Vector y) override;
    void release() override;
    int advance(double t, double dt, double& reached) override;
    std::string flagName(int flag) const override;
    double nextStep() const override;
    void addCounts(Counts& counts) const override;

private:
    static int rightHandSide(double t, N_Vector y, N_Vector ydot, void* self);

    std::string table_;
    AdaptivityOptions adaptivity_;
};

}  // namespace sph
