// surgeFront: the leading fluid particle's distance from `origin` along `direction`, over time
// (dam-break surge front, Martin & Moyce 1952). Writes postProcessing/<name>/<t0>/surgeFront.dat
// with columns: time, front.
// Example (system/controlDict, functions):
//   front { type surgeFront; origin (0 0); direction (1 0); executeInterval 0.005; }
#pragma once

#include "core/Vector.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/TimeSeriesFile.hpp"


namespace sph {

template <int D>
class SurgeFront : public FunctionObject<D> {
public:
    SurgeFront(const Dictionary& dict, const FunctionObjectContext& context);
    std::string describe() const override;
    void execute(const FluidSystem<D>& system, double t) override;

private:
    Vec<D> origin_, direction_;
    TimeSeriesFile out_;
};

}  // namespace sph
