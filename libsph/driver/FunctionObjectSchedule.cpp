#include "driver/FunctionObjectSchedule.hpp"

#include "io/AtomicFile.hpp"
#include "io/SelectByType.hpp"
#include "io/TimeName.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace sph {

template <int D>
FunctionObjectSchedule<D>::FunctionObjectSchedule(const Dictionary& controlDict, const std::filesystem::path& caseDirectory, double startTime,
                                                  double rho0, const FluidSystemView<D>& system,
                                                  const std::function<void(std::size_t)>& recordPatchLoad, const Reductions& reductions)
    : reductions_(reductions) {
    const Dictionary* functions = controlDict.findSubDict("functions");
    if (!functions) return;
    const auto registry = makeFunctionObjectRegistry<D>();
    for (const std::string& name : functions->keywords())
        reductions.together([&] {
            const Dictionary& dict = functions->subDict(name);
            const FunctionObjectContext<D> context{
                caseDirectory, caseDirectory / "postProcessing" / name / timeName(startTime), rho0, system, reductions, recordPatchLoad};
            auto object = selectByType(registry, dict, dict, context);
            const double interval = dict.getNonNegativeOrDefault("executeInterval", 0.0);
            fmt::print("Selecting function object {} ({})\n", name, object->describe());
            entries_.push_back({name, std::move(object), interval, startTime});
        });
}

template <int D>
bool FunctionObjectSchedule<D>::dueAt(double t) const {
    return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& entry) { return isDue(entry, t); });
}

template <int D>
void FunctionObjectSchedule<D>::execute(const FluidSystemView<D>& system, double t, bool force) {
    for (Entry& entry : entries_) {
        if (!force && !isDue(entry, t)) continue;
        reductions_.together([&] { entry.object->execute(system, t); });
        while (entry.nextTime <= t + 1e-6 * entry.interval && entry.interval > 0.0) entry.nextTime += entry.interval;
    }
}

template <int D>
void FunctionObjectSchedule<D>::reportErrorAgainstCost(const std::filesystem::path& caseDirectory, double startTime, const RunCost& cost) const {
    std::vector<std::string> figures;
    std::string csv = "functionObject,quantity,L1,L2,Linf,normalisation,wallTime_s,fluidParticles,steps,particleSteps_per_s,startTime,endTime\n";
    const double rate = cost.wallSeconds > 0.0 ? static_cast<double>(cost.fluidParticles) * static_cast<double>(cost.steps) / cost.wallSeconds : 0.0;
    for (const Entry& entry : entries_)
        for (const ReportedError& error : entry.object->errors()) {
            figures.push_back(std::isnan(error.norms.l1)
                                  ? fmt::format("{} {}: nothing compared ({})", entry.name, error.quantity, error.normalisation)
                                  : fmt::format("{} {}: L1 {:.3e}, L2 {:.3e}, Linf {:.3e} ({})", entry.name, error.quantity, error.norms.l1,
                                                error.norms.l2, error.norms.linf, error.normalisation));
            csv += fmt::format("{},{},{:.6e},{:.6e},{:.6e},\"{}\",{:.4f},{},{},{:.6e},{:.9g},{:.9g}\n", entry.name, error.quantity, error.norms.l1,
                               error.norms.l2, error.norms.linf, error.normalisation, cost.wallSeconds, cost.fluidParticles, cost.steps, rate,
                               startTime, cost.endTime);
        }
    if (figures.empty() || !reductions_.writesFiles()) return;
    fmt::print("Error against run time: {}; wall time {:.2f} s, {} fluid particles, {} steps\n", fmt::join(figures, "; "), cost.wallSeconds,
               cost.fluidParticles, cost.steps);
    const auto directory = caseDirectory / "postProcessing" / "summary" / timeName(startTime);
    std::filesystem::create_directories(directory);
    writeTextAtomically(directory / "summary.csv", csv);
}

#ifdef SPHKIT_HAS_1D
template class FunctionObjectSchedule<1>;
#endif
#ifdef SPHKIT_HAS_2D
template class FunctionObjectSchedule<2>;
#endif
#ifdef SPHKIT_HAS_3D
template class FunctionObjectSchedule<3>;
#endif

}  // namespace sph
