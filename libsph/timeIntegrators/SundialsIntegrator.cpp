#include "timeIntegrators/SundialsIntegrator.hpp"

#include "timeIntegrators/StateOverRanks.hpp"

namespace sph {

template <int D>
double SundialsIntegrator<D>::takeStep(IntegrableSystem<D>& system, double t, double dt) {
    system_ = &system;
    // On several ranks every rank restarts or resizes together: the vector is made over all of them.
    bool restart = restart_ || !memory_, migrated = migrated_;
    if (system.stateOverRanks) {
        restart = system.stateOverRanks->onAnyRank(restart);
        migrated = system.stateOverRanks->onAnyRank(migrated);
    }
    if (restart || migrated) {
        N_Vector y = state_.wrap(system);
        if (!restart && resize(system, t, y)) {
            ++resizes_;
        } else {
            if (memory_) {
                addCounts(beforeRestarts_);
                release();
                ++restarts_;
            }
            create(system, t, y, nextStep_);
        }
        state_.markEvaluated(system, t);  // on entry the rates at t are current
        restart_ = migrated_ = false;
    }
    double reached = t;
    const int flag = advance(t, dt, reached);
    if (flag < 0) failIntegration(solverName_, flagName(flag), reached, state_.lastFailure());
    nextStep_ = nextStep();
    state_.evaluateAtStepEnd(system, reached, [&](double time, RateTerms terms) { this->evaluate(system, time, terms); });
    return reached - t;
}

template <int D>
int SundialsIntegrator<D>::rates(double t, N_Vector y, N_Vector ydot, RateTerms terms) {
    return state_.rates(*system_, t, y, ydot, terms, [this](double time, RateTerms part) { this->evaluate(*system_, time, part); });
}

template <int D>
int SundialsIntegrator<D>::viscousJacobianTimes(double t, N_Vector w, N_Vector Jw, N_Vector y, N_Vector fy) {
    return state_.viscousJacobianTimes(*system_, t, w, Jw, y, fy, [this](double time, RateTerms part) { this->evaluate(*system_, time, part); });
}

template <int D>
std::vector<std::pair<std::string, long>> SundialsIntegrator<D>::counters() const {
    auto result = TimeIntegrator<D>::counters();
    Counts counts = beforeRestarts_;
    if (memory_) addCounts(counts);
    result.emplace_back("rejected steps (error test)", counts.rejected);
    result.emplace_back("restarts", restarts_);
    result.emplace_back("resizes (particles crossed or removed)", resizes_);
    if (!implicitSolve_) return result;
    result.emplace_back("nonlinear iterations", counts.nonlinearIterations);
    result.emplace_back("nonlinear convergence failures", counts.nonlinearFailures);
    result.emplace_back("linear iterations", counts.linearIterations);
    return result;
}

template class SundialsIntegrator<1>;
template class SundialsIntegrator<2>;
template class SundialsIntegrator<3>;

}  // namespace sph
