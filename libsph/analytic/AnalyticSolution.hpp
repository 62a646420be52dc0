// Analytic (or ODE) solutions a run is compared with, selected by name where a case names a
// reference field: the errorNorm function object, and a fluid region's initial velocity.
//   solution { type taylorGreen; U 1; L 1; nu 0.01; }
// A solution gives the velocity and, where it has one, the pressure at a point and time; the
// hydrostatic solution reads the case's gravity and rho0 from FlowConstants.
#pragma once

#include "core/Registry.hpp"
#include "core/Vector.hpp"
#include "io/Dictionary.hpp"

#include <memory>

namespace sph {

template <int D>
struct FlowConstants {
    double rho0;
    Vec<D> gravity;  // at the time of evaluation (a ramped gravity included)
};

template <int D>
class AnalyticSolution {
public:
    virtual ~AnalyticSolution() = default;
    virtual Vec<D> velocity(const Vec<D>& x, double t) const = 0;
    virtual bool hasPressure() const { return false; }
    virtual double pressure(const Vec<D>& x, double t, const FlowConstants<D>& constants) const;
};

template <int D>
using AnalyticSolutionRegistry = Registry<std::unique_ptr<AnalyticSolution<D>>, const Dictionary&>;

template <int D>
AnalyticSolutionRegistry<D> makeAnalyticSolutionRegistry();

}  // namespace sph
