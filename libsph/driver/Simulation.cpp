#include "driver/Simulation.hpp"

#include "driver/BlowUpCheck.hpp"
#include "driver/CaseDirectory.hpp"
#include "driver/FluidSetup.hpp"
#include "driver/Progress.hpp"
#include "driver/RestartState.hpp"
#include "driver/RunControls.hpp"
#include "driver/StopRequest.hpp"
#include "driver/Threads.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "io/AtomicFile.hpp"
#include "io/ParticleCsv.hpp"
#include "io/ParticleFile.hpp"
#include "io/PvdCollection.hpp"
#include "io/SelectByType.hpp"
#include "io/TimeName.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace sph {

namespace {

// Reordering the fluid by cell costs a pass over every field; particles move little per step.
constexpr long stepsBetweenCellSorts = 10;

template <int D>
struct FunctionObjectEntry {
    std::string name;
    std::unique_ptr<FunctionObject<D>> object;
    double interval;
    double nextTime;
};

template <int D>
std::vector<FunctionObjectEntry<D>> readFunctionObjects(const Dictionary& controlDict, const std::filesystem::path& caseDirectory, double startTime,
                                                        double rho0, const FluidSystem<D>& system) {
    std::vector<FunctionObjectEntry<D>> entries;
    const Dictionary* functions = controlDict.findSubDict("functions");
    if (!functions) return entries;
    const auto registry = makeFunctionObjectRegistry<D>();
    for (const std::string& name : functions->keywords()) {
        const Dictionary& dict = functions->subDict(name);
        const FunctionObjectContext<D> context{caseDirectory, caseDirectory / "postProcessing" / name / timeName(startTime), rho0, system.view()};
        auto object = selectByType(registry, dict, dict, context);
        const double interval = dict.getNonNegativeOrDefault("executeInterval", 0.0);
        fmt::print("Selecting function object {} ({})\n", name, object->describe());
        entries.push_back({name, std::move(object), interval, startTime});
    }
    return entries;
}

struct RunCost {
    double wallSeconds;
    std::size_t fluidParticles;
    long steps;
};

// A run whose function objects compare with a reference ends with one line of every error
// against the run's cost, and the same in postProcessing/summary/<startTime>/summary.csv.
template <int D>
void reportErrorAgainstCost(const std::vector<FunctionObjectEntry<D>>& functionObjects, const std::filesystem::path& caseDirectory, double startTime,
                            double endTime, const RunCost& cost) {
    std::vector<std::string> figures;
    std::string csv = "functionObject,quantity,L1,L2,Linf,normalisation,wallTime_s,fluidParticles,steps,particleSteps_per_s,startTime,endTime\n";
    const double rate = cost.wallSeconds > 0.0 ? static_cast<double>(cost.fluidParticles) * static_cast<double>(cost.steps) / cost.wallSeconds : 0.0;
    for (const auto& entry : functionObjects)
        for (const ReportedError& error : entry.object->errors()) {
            figures.push_back(fmt::format("{} {}: L1 {:.3e}, L2 {:.3e}, Linf {:.3e} ({})", entry.name, error.quantity, error.norms.l1, error.norms.l2,
                                          error.norms.linf, error.normalisation));
            csv += fmt::format("{},{},{:.6e},{:.6e},{:.6e},\"{}\",{:.4f},{},{},{:.6e},{:.9g},{:.9g}\n", entry.name, error.quantity, error.norms.l1,
                               error.norms.l2, error.norms.linf, error.normalisation, cost.wallSeconds, cost.fluidParticles, cost.steps, rate,
                               startTime, endTime);
        }
    if (figures.empty()) return;
    fmt::print("Error against run time: {}; wall time {:.2f} s, {} fluid particles, {} steps\n", fmt::join(figures, "; "), cost.wallSeconds,
               cost.fluidParticles, cost.steps);
    const auto directory = caseDirectory / "postProcessing" / "summary" / timeName(startTime);
    std::filesystem::create_directories(directory);
    writeTextAtomically(directory / "summary.csv", csv);
}

template <int D>
void run(const std::filesystem::path& caseDirectory, const Dictionary& controlDict, const TimeDirectory& start, RunMode mode,
         std::optional<int> threads) {
    CaseSetup<D> setup = setUpCase<D>(caseDirectory, start);
    FluidSystem<D>& system = *setup.system;
    const RunThreads runThreads(system.fluid.size() + system.walls.size(), D, threads);
    TimeIntegrator<D>& integrator = *setup.integrator;
    // The exact time from the state file: a directory name holds only its first digits.
    const double startTime = setup.header.time;
    const double c0 = std::visit([](const auto& eos) { return eos.c0; }, system.models().eos);

    RunControls controls = RunControls::read(controlDict);
    const bool writeCsv = controlDict.getOrDefault("writeCsv", false);
    ControlDictWatcher watcher(caseDirectory / "system/controlDict", controlDict.getOrDefault("runTimeModifiable", true));
    if (mode == RunMode::TimeLoop && !(controls.endTime > startTime))
        controlDict.fail("endTime", fmt::format("must be later than the start time {:g}, found {:g}", startTime, controls.endTime));
    for (const Patch<D>& patch : system.patches)
        if (patch.motion) patch.motion->checkCovers(startTime, controls.endTime);
    auto functionObjects = readFunctionObjects<D>(controlDict, caseDirectory, startTime, setup.rho0, system);
    controlDict.checkUnused();
    for (const Dictionary& dict : setup.dictionaries) dict.checkUnused();

    PvdCollection pvd(caseDirectory / (caseName(caseDirectory) + ".pvd"));
    for (const TimeDirectory& written : findTimeDirectories(caseDirectory))
        if (written.time <= start.time)
            pvd.add(written.time, {written.path.filename().string() + "/fluid.vtu", written.path.filename().string() + "/walls.vtu"});

    StateHeader header = setup.header;
    const auto writeState = [&](const std::filesystem::path& directory, double t, long step) {
        header.time = t;
        header.step = step;
        collectRestartState(system, integrator, setup.integratorType, header);
        StateHeader wallHeader = header;
        wallHeader.patchNames = setup.patchNames;
        writeParticleFile(directory / "fluid.vtu", system.fluid, header);
        writeParticleFile(directory / "walls.vtu", system.walls, wallHeader);
    };
    const auto write = [&](double t, long step) {
        auto timer = system.timers.time(Stage::Output);
        const std::string name = timeName(t);
        writeDirectoryAtomically(caseDirectory / name, [&](const std::filesystem::path& directory) {
            writeState(directory, t, step);
            if (writeCsv) {
                writeParticleCsv(directory / "fluid.csv", system.fluid);
                writeParticleCsv(directory / "walls.csv", system.walls);
            }
        });
        pvd.add(t, {name + "/fluid.vtu", name + "/walls.vtu"});
    };
    if (mode == RunMode::RatesOnly) {
        system.evaluateRates(startTime);
        const auto directory = caseDirectory / "postProcessing" / "rates" / timeName(startTime);
        writeDirectoryAtomically(directory, [&](const std::filesystem::path& temporary) {
            writeState(temporary, startTime, header.step);
            writeParticleCsv(temporary / "fluid.csv", system.fluid);
            writeParticleCsv(temporary / "walls.csv", system.walls);
        });
        fmt::print("\nWrote the right-hand side at t = {:g} to {}\n", startTime, directory.string());
        return;
    }
    const auto runFunctionObjects = [&](double t, bool force) {
        auto timer = system.timers.time(Stage::FunctionObjects);
        for (auto& entry : functionObjects) {
            // Executes at the first step at or after each multiple of the interval, and at the end.
            if (!force && t < entry.nextTime - 1e-6 * entry.interval) continue;
            entry.object->execute(system.view(), t);
            while (entry.nextTime <= t + 1e-6 * entry.interval && entry.interval > 0.0) entry.nextTime += entry.interval;
        }
    };

    fmt::print("\nStarting time loop at t = {:g} (from {}), endTime {:g}, writeInterval {:g}\n\n", startTime, start.path.string(), controls.endTime,
               controls.writeInterval);
    double t = startTime;
    long step = header.step;
    restoreRestartState(system, integrator, setup.integratorType, setup.header, t, (start.path / "fluid.vtu").string());
    runFunctionObjects(t, true);
    Progress progress(t, controls.endTime, system.fluid.size());
    double nextWrite = controls.nextWriteAfter(t);
    const long firstStep = step;
    double dt = 0.0;
    const StopRequest stopRequest;
    while (true) {
        const double timeTolerance = 1e-9 * controls.writeInterval;
        if (t >= controls.endTime - timeTolerance) break;
        // Counted from the run's first step, not this invocation's, so a restart sorts when the uninterrupted run did.
        if (integrator.allowsReordering() && step % stepsBetweenCellSorts == 0) {
            system.sortFluidByCell();
            integrator.stateChangedOutside();
        }
        dt = setup.fixedDeltaT > 0.0 ? setup.fixedDeltaT
                                     : std::min(system.stableTimeStep(setup.courant, !integrator.viscosityImplicit()), setup.maxDeltaT);
        // Land on write times and on endTime exactly.
        const double target = std::min(nextWrite, controls.endTime);
        if (t + dt > target - timeTolerance) dt = target - t;
        const double taken = integrator.step(system, t, dt);
        if (system.shiftsParticles()) {
            system.shiftParticles(taken);
            integrator.stateChangedOutside();
        }
        if (system.wrapPeriodic()) integrator.stateChangedOutside();
        t = (taken >= dt && t + dt > target - timeTolerance) ? target : t + taken;
        ++step;
        checkFluidState(system.fluid, system.domainMin(), system.domainMax(), {c0, setup.rho0}, step, t);
        const bool last = t >= controls.endTime - timeTolerance;
        if (const int signal = stopRequest.signal(); signal != 0 && !last) {
            runFunctionObjects(t, true);
            write(t, step);
            progress.finish();
            fmt::print("\n{} received: stopped at step {}, t = {:.9g}, and wrote the state to {}; rerun to continue from it\n", signalName(signal),
                       step, t, (caseDirectory / timeName(t)).string());
            break;
        }
        runFunctionObjects(t, last);
        if (t >= nextWrite - timeTolerance || last) {
            write(t, step);
            nextWrite = controls.nextWriteAfter(t);
        }
        progress.update(step, t, taken);
        if (const auto changed = watcher.changed(controls, t)) {
            controls = *changed;
            nextWrite = controls.nextWriteAfter(t);
            progress.setEndTime(controls.endTime);
        }
    }
    progress.finish();

    const double wall = progress.elapsedSeconds();
    const long steps = step - firstStep;
    const double particleSteps = static_cast<double>(steps) * static_cast<double>(system.fluid.size());
    fmt::print("\nEnd at t = {:g}: {} steps, {} fluid + {} wall particles\n", t, steps, system.fluid.size(), system.walls.size());
    fmt::print("Wall time {:.2f} s, {:.3g} particle-steps/s\n", wall, wall > 0.0 ? particleSteps / wall : 0.0);
    fmt::print("Integrator counters:\n");
    for (const auto& [name, value] : integrator.counters()) fmt::print("    {:<32} {}\n", name, value);
    fmt::print("Time per part:\n");
    double accounted = 0.0;
    const auto printPart = [&](std::string_view name, double seconds) {
        fmt::print("    {:<20} {:8.3f} s  {:5.1f} %\n", name, seconds, wall > 0.0 ? 100.0 * seconds / wall : 0.0);
    };
    for (std::size_t s = 0; s < static_cast<std::size_t>(Stage::Count); ++s) {
        const double seconds = system.timers.seconds(static_cast<Stage>(s));
        accounted += seconds;
        printPart(stageNames[s], seconds);
    }
    printPart("other", std::max(0.0, wall - accounted));  // solver internals (SUNDIALS), checks, progress
    reportErrorAgainstCost(functionObjects, caseDirectory, startTime, t, {wall, system.fluid.size(), steps});
}

}  // namespace

void runCase(const std::filesystem::path& caseDirectory, RunMode mode, bool overwriteLaterTimes, std::optional<int> threads) {
    if (!std::filesystem::is_directory(caseDirectory)) throw FatalError("error: case directory '" + caseDirectory.string() + "' does not exist");
    const Dictionary controlDict = readCaseDictionary(caseDirectory, "system/controlDict");
    controlDict.findEntry("application");  // informational, as in OpenFOAM
    if (mode == RunMode::TimeLoop) removeIncompleteOutput(caseDirectory);
    const TimeDirectory start = selectStartTime(caseDirectory, controlDict);
    if (const std::vector<TimeDirectory> later = timesAfter(caseDirectory, start.time); mode == RunMode::TimeLoop && !later.empty()) {
        if (!overwriteLaterTimes) {
            std::string names;
            for (const TimeDirectory& t : later) names += " " + t.path.filename().string();
            controlDict.fail("startFrom", fmt::format("the run starts at t = {:g}, but the case has later times (written by an earlier run):{}; "
                                                      "the run would overwrite them. Start from latestTime, remove them, or run wcsph "
                                                      "-overwrite to have them removed",
                                                      start.time, names));
        }
        removeTimeDirectories(later);
    }
    const int dimension = readParticleFileHeader(start.path / "fluid.vtu").dimension;
    switch (dimension) {
#ifdef SPHKIT_HAS_1D
        case 1: return run<1>(caseDirectory, controlDict, start, mode, threads);
#endif
#ifdef SPHKIT_HAS_2D
        case 2: return run<2>(caseDirectory, controlDict, start, mode, threads);
#endif
#ifdef SPHKIT_HAS_3D
        case 3: return run<3>(caseDirectory, controlDict, start, mode, threads);
#endif
        default: break;
    }
    throw FatalError(fmt::format("error: '{}' is a {}D state, but this build compiled only the dimensions in SPHKIT_DIMENSIONS",
                                 (start.path / "fluid.vtu").string(), dimension));
}

}  // namespace sph
