// SUNDIALS CVODE with BDF (orders 1 to maxOrder), fully implicit: the whole right-hand side
// in a Newton iteration with SUNDIALS' matrix-free GMRES and difference-quotient
// Jacobian-vector products. For fully stiff runs: the step is set by the tolerances, capped by
// the acoustic and force limits times courant (which may exceed 1), not by the viscous limit.
// BDF keeps past steps, so the fluid is not reordered by cell during the run; a periodic wrap
// restarts the method at order 1.
// Reference: A.C. Hindmarsh et al., ACM Trans. Math. Softw. 31 (2005) 363-396; SUNDIALS 6.4
// CVODE user guide.
// Example (system/timeIntegration):
//   integrator { type cvode; relativeTolerance 1e-4; absoluteTolerance 1e-6; maxOrder 5; maxKrylovDimension 10; }
#pragma once

#include "timeIntegrators/SundialsIntegrator.hpp"

namespace sph {

template <int D>
class CvodeBdf : public SundialsIntegrator<D> {
public:
    CvodeBdf(SundialsTolerances tolerances, int maxOrder, KrylovOptions krylov);
    ~CvodeBdf() override;
    std::string describe() const override;
    bool viscosityImplicit() const override { return true; }
    bool allowsReordering() const override { return false; }

protected:
    using typename SundialsIntegrator<D>::Counts;
    void create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) override;
    void release() override;
    int advance(double t, double dt, double& reached) override;
    std::string flagName(int flag) const override;
    double nextStep() const override;
    void addCounts(Counts& counts) const override;

private:
    static int rightHandSide(double t, N_Vector y, N_Vector ydot, void* self);

    SundialsTolerances tolerances_;
    int maxOrder_;
    KrylovOptions krylov_;
    SUNLinearSolver linearSolver_ = nullptr;
};

}  // namespace sph
