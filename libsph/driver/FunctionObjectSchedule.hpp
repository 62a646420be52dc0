// The function objects of controlDict's `functions`, each executed at its executeInterval, and
// the run's closing line of every error they measured against the run's cost.
#pragma once

#include "io/Dictionary.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "physics/FluidSystemView.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sph {

struct RunCost {
    double wallSeconds;
    std::size_t fluidParticles;
    long steps;
    double endTime;
};

template <int D>
class FunctionObjectSchedule {
public:
    // Selects each entry of `functions` by its type; none when controlDict has no `functions`.
    // In a decomposed run every rank selects them, on its share (`system`), and they combine
    // over the ranks by `reductions`: each construction and execution is collective.
    // recordPatchLoad: FunctionObjectContext's.
    FunctionObjectSchedule(const Dictionary& controlDict, const std::filesystem::path& caseDirectory, double startTime, double rho0,
                           const FluidSystemView<D>& system, const std::function<void(std::size_t)>& recordPatchLoad,
                           const Reductions& reductions = Reductions::oneProcess());

    // Executes each object at the first step at or after each multiple of its interval, or
    // every object when `force` (the start, the end, a stop).
    void execute(const FluidSystemView<D>& system, double t, bool force);
    // Whether execute(system, t, false) would execute any object.
    bool dueAt(double t) const;
    bool empty() const { return entries_.empty(); }

    // One console line of every error against the run's cost, and the same in
    // postProcessing/summary/<startTime>/summary.csv; nothing when no object compares.
    void reportErrorAgainstCost(const std::filesystem::path& caseDirectory, double startTime, const RunCost& cost) const;

private:
    struct Entry {
        std::string name;
        std::unique_ptr<FunctionObject<D>> object;
        double interval;
        double nextTime;
    };
    static bool isDue(const Entry& entry, double t) { return t >= entry.nextTime - 1e-6 * entry.interval; }
    std::vector<Entry> entries_;
    const Reductions& reductions_;
};

}  // namespace sph
