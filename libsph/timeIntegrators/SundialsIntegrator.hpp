// What the SUNDIALS integrators (ARKODE ERKStep, ARKODE ARKStep, CVODE) share: one SUNDIALS
// step per driver step, with the driver's step as the stop time (and as the step when fixed);
// a restart from the particle arrays after the driver reordered or wrapped them, keeping the
// step size it would take next (not the last one taken, which the driver's stop time may have
// cut short: restarting from that after every shift shrank an adaptive step 10,000-fold); the
// state's rates evaluated at the end of each step; the counters.
#pragma once

#include "timeIntegrators/SundialsState.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <cmath>

namespace sph {

template <int D>
class SundialsIntegrator : public TimeIntegrator<D> {
public:
    void stateChangedOutside() override { restart_ = true; }
    void particlesMigrated() override { migrated_ = true; }
    // A restarted run starts from the step size it would have taken next; the error controller's history and
    // CVODE's BDF history are rebuilt, so it agrees with the uninterrupted run to the tolerances.
    std::vector<double> savedState() const override { return {nextStep_}; }
    void resume(const IntegrableSystem<D>&, const std::vector<double>& saved) override {
        if (saved.size() == 1 && saved[0] > 0.0 && std::isfinite(saved[0])) nextStep_ = saved[0];
    }
    std::vector<std::pair<std::string, long>> counters() const override;

protected:
    struct Counts {
        long rejected = 0, nonlinearIterations = 0, nonlinearFailures = 0, linearIterations = 0;
    };

    explicit SundialsIntegrator(std::string solverName, bool implicitSolve) : solverName_(std::move(solverName)), implicitSolve_(implicitSolve) {}
    double takeStep(IntegrableSystem<D>& system, double t, double dt) final;

    // One SUNDIALS package: create its memory at (t, y) with `initialStep` (0: its own guess),
    // free it, take one step to at most t + dt, name a return flag, read the step it would take next and its counters.
    virtual void create(IntegrableSystem<D>& system, double t, N_Vector y, double initialStep) = 0;
    // Hands the package a vector of other length at t, keeping its step size and error history;
    // false where it cannot (then it is created again).
    virtual bool resize(IntegrableSystem<D>& /*system*/, double /*t*/, N_Vector /*y*/) { return false; }
    virtual void release() = 0;
    virtual int advance(double t, double dt, double& reached) = 0;
    virtual std::string flagName(int flag) const = 0;
    virtual double nextStep() const = 0;
    virtual void addCounts(Counts& counts) const = 0;

    // The right-hand side of the given terms at (t, y), for the packages' callbacks.
    int rates(double t, N_Vector y, N_Vector ydot, RateTerms terms);
    int viscousJacobianTimes(double t, N_Vector w, N_Vector Jw, N_Vector y, N_Vector fy);

    SundialsState<D> state_;
    void* memory_ = nullptr;
    IntegrableSystem<D>* system_ = nullptr;

private:
    std::string solverName_;
    bool implicitSolve_;
    bool restart_ = true;
    bool migrated_ = false;
    double nextStep_ = 0.0;
    Counts beforeRestarts_;
    // Created again after the first creation, and handed a vector of other length (several
    // ranks: particles crossed between two cell sorts).
    long restarts_ = 0, resizes_ = 0;
};

}  // namespace sph
