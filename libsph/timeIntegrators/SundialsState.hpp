// The bridge between SUNDIALS and an IntegrableSystem, shared by the ARKODE and CVODE integrators.
//
// The state vector is an N_Vector ManyVector whose serial subvectors wrap the particle arrays
// themselves (fluid position, velocity, and each density that follows the continuity
// equation): SUNDIALS writes each step's solution straight into the particles. The right-hand
// side loads the stage vector it is given into the particle arrays (skipped when it is the
// wrapped vector), evaluates, and returns (v, a, drho). It catches every exception and
// non-finite rate and returns a recoverable error, so an adaptive integrator retries smaller;
// the message is kept for the report if the step fails for good.
//
// On several ranks (IntegrableSystem::stateOverRanks) each rank's subvectors hold copies of the
// values of the particles it owns, and the vector is an MPI ManyVector: SUNDIALS' norms and dot
// products sum over every rank, so every rank takes the same steps. Loading a vector writes the
// owned particles and refreshes their copies on the other ranks; every decision that leads to
// an exchange (evaluate or answer from the arrays, a failed evaluation) is taken together. An
// exception inside an evaluation stops every rank (StateOverRanks::stopAll).
//
// Evaluating at the end of a step keeps the driver's rates current; an explicit method's first
// stage of the next step asks for the same (t, y), which is then answered from the arrays. A
// table whose last stage is the step's end (first same as last) evaluated it there already.
#pragma once

#include "io/Dictionary.hpp"
#include "timeIntegrators/IntegrableSystem.hpp"

#include <nvector/nvector_manyvector.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sph {

// Relative and absolute tolerances; the absolute one is scaled per block by h (positions),
// c0 (velocities) and rho0 (densities), so one number fits every case.
struct SundialsTolerances {
    double relative = 1e-4;
    double absolute = 1e-6;
};

SundialsTolerances readTolerances(const Dictionary& dict);

// Fixed step, or adaptive with tolerances and ARKODE's adaptivity controller chosen by name
// among `controllers`.
struct AdaptivityOptions {
    bool adaptive = false;
    SundialsTolerances tolerances;
    int controller = 0;  // ARKODE's adaptivity method: 0 PID, 1 PI, 2 I, 3 explicit, 4 implicit, 5 ImEx Gustafsson
    std::string controllerName = "PID";
};

AdaptivityOptions readAdaptivity(const Dictionary& dict, const std::vector<std::string>& controllers);

// The Krylov solver of the implicit integrators: SUNDIALS' GMRES, matrix-free.
enum class JacobianTimesVector { DifferenceQuotient, VelocityBlock };
struct KrylovOptions {
    int maxKrylovDimension = 10;
    JacobianTimesVector jacobian = JacobianTimesVector::DifferenceQuotient;
};

int readMaxKrylovDimension(const Dictionary& dict);
KrylovOptions readKrylovOptions(const Dictionary& dict);

template <int D>
class SundialsState {
public:
    SundialsState();
    ~SundialsState();
    SundialsState(const SundialsState&) = delete;
    SundialsState& operator=(const SundialsState&) = delete;

    SUNContext context() const { return context_; }

    // (Re)wraps the particle arrays; call after the system's arrays moved (reordering).
    // Collective on several ranks.
    N_Vector wrap(IntegrableSystem<D>& system);
    N_Vector wrapped() const { return wrapped_; }

    // The system's rates at the end of a step, at time t and the wrapped vector's state: taken
    // from its last evaluation where that was there (an explicit table whose last stage is the
    // step's end, first same as last), else the vector loaded into the particle arrays (a serial
    // run's arrays are the vector already) and evaluated. Collective on several ranks.
    void evaluateAtStepEnd(IntegrableSystem<D>& system, double t, const std::function<void(double, RateTerms)>& evaluate);

    // Per-component absolute tolerances, scaled as in SundialsTolerances.
    N_Vector absoluteTolerances(const IntegrableSystem<D>& system, double absolute);

    // The right-hand side f(t, y) -> ydot of the given terms; returns 0, or 1 (recoverable).
    // `evaluate` runs the system's evaluation (the integrator counts it).
    int rates(IntegrableSystem<D>& system, double t, N_Vector y, N_Vector ydot, RateTerms terms,
              const std::function<void(double, RateTerms)>& evaluate);

    // J w for the implicit viscous part with positions and densities frozen: the viscous
    // acceleration is linear in velocity (laminar viscosity), so J w = a_v(v + w) - a_v(v).
    int viscousJacobianTimes(IntegrableSystem<D>& system, double t, N_Vector w, N_Vector Jw, N_Vector y, N_Vector fy,
                             const std::function<void(double, RateTerms)>& evaluate);

    // Records that the system's rates are all evaluated at t and at the state its arrays hold
    // now, keeping a copy of that state: SUNDIALS may later write stage values into the very
    // arrays it wraps.
    void markEvaluated(IntegrableSystem<D>& system, double t);

    // The message of the last failed right-hand side, for the error report.
    const std::string& lastFailure() const { return lastFailure_; }

private:
    // One array of the state: `width` values per particle, `held` particles, of which the
    // vector holds those `owned` marks (all where it is null).
    struct Block {
        double* data;
        std::size_t width, held;
        const std::vector<char>* owned;
        std::size_t length() const;  // values in the vector
    };
    // The state's arrays: fluid position and velocity, the evolved densities; `values` names
    // the array in their place (acceleration and density rates for the right-hand side).
    enum class Values { State, Rates };
    std::vector<Block> blocks(IntegrableSystem<D>& system, Values values = Values::State) const;
    double* part(N_Vector v, std::size_t k) const { return subvectorData_(v, static_cast<sunindextype>(k)); }
    void load(IntegrableSystem<D>& system, N_Vector y);
    bool isEvaluatedState(IntegrableSystem<D>& system, N_Vector y) const;
    // The evaluated rates into ydot; the first non-finite one's description, or empty.
    std::string storeRates(IntegrableSystem<D>& system, double t, N_Vector y, N_Vector ydot, bool viscousOnly);

    SUNContext context_ = nullptr;
    double* (*subvectorData_)(N_Vector, sunindextype) = N_VGetSubvectorArrayPointer_ManyVector;
    std::vector<N_Vector> parts_;
    N_Vector wrapped_ = nullptr;
    N_Vector absoluteTolerances_ = nullptr;
    std::vector<double> evaluatedState_;  // where the system's rates were last evaluated, at evaluatedTime_
    double evaluatedTime_ = 0.0;
    bool evaluatedValid_ = false;
    std::string lastFailure_;
};

// A string SUNDIALS allocated (a return flag's name), freed once copied.
std::string takeSundialsString(char* allocated);

// Throws the FatalError for a SUNDIALS failure: the solver's flag name and, when the
// right-hand side failed, why.
[[noreturn]] void failIntegration(const std::string& solver, const std::string& flagName, double t, const std::string& rightHandSideFailure);

}  // namespace sph
