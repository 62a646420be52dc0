// The time-integrator family. An integrator advances an IntegrableSystem's state (fluid position,
// velocity, density with continuity, and wall density where a boundary model evolves it)
// by one step, calling evaluate() for the right-hand side. On entry the rates at the start of
// the step are current; on exit they are current at its end.
#pragma once

#include "core/Registry.hpp"
#include "io/Dictionary.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sph {

template <int D>
class IntegrableSystem;

enum class RateTerms;

template <int D>
class TimeIntegrator {
public:
    virtual ~TimeIntegrator() = default;
    virtual std::string describe() const = 0;

    // Advances from t by dt, or by less where an adaptive integrator's error control asks;
    // returns the step taken.
    double step(IntegrableSystem<D>& system, double t, double dt) {
        ++steps_;
        return takeStep(system, t, dt);
    }

    // The driver changed the state between steps (periodic wrap, particles reordered by cell):
    // an integrator that keeps state of its own restarts from the system's.
    virtual void stateChangedOutside() {}
    // A decomposed run moved particles between its ranks, the state itself unchanged: an
    // integrator that holds this rank's particles takes the new set, keeping its history where
    // it can.
    virtual void particlesMigrated() { stateChangedOutside(); }

    // Restart: what the integrator carries from step to step besides particle fields, written
    // with each state, and handed back before the first step of a restarted run (an empty
    // `saved`: the state was written by another integrator, or by generateParticles).
    virtual std::vector<double> savedState() const { return {}; }
    virtual void resume(const IntegrableSystem<D>& /*system*/, const std::vector<double>& /*saved*/) {}
    // True when the rates it ends a step with were evaluated at a predicted state, not the one
    // written: a restart then keeps the written rates instead of re-evaluating them.
    virtual bool carriesPredictedRates() const { return false; }

    // Capabilities the driver and the case reader check.
    virtual bool viscosityImplicit() const { return false; }  // no explicit viscous step limit
    virtual bool allowsReordering() const { return true; }    // false: history that reordering would break
    virtual bool advancesFreeBodies() const { return false; }

    // Stops before the first step if the case selected what this integrator cannot advance;
    // `dict` is the integrator's dictionary, for the message.
    virtual void checkCompatible(const IntegrableSystem<D>& system, const Dictionary& dict) const;

    // Name and value of each counter, for the end-of-run report.
    virtual std::vector<std::pair<std::string, long>> counters() const;
    // The counters as the run report prints them (the same on every rank of a parallel run).
    std::string countersReport() const;
    long rateEvaluations() const { return evaluations_; }

protected:
    virtual double takeStep(IntegrableSystem<D>& system, double t, double dt) = 0;
    void evaluate(IntegrableSystem<D>& system, double t);
    void evaluate(IntegrableSystem<D>& system, double t, RateTerms terms);
    // The step's last evaluation, at the state the step ends with (its positions and densities).
    void evaluateAtStepEnd(IntegrableSystem<D>& system, double t);
    long steps() const { return steps_; }

private:
    long steps_ = 0;
    long evaluations_ = 0;
};

template <int D>
using TimeIntegratorRegistry = Registry<std::unique_ptr<TimeIntegrator<D>>, const Dictionary&>;

template <int D>
TimeIntegratorRegistry<D> makeTimeIntegratorRegistry();

}  // namespace sph
