#include "driver/Simulation.hpp"

#include "driver/BlowUpCheck.hpp"
#include "driver/CaseDirectory.hpp"
#include "driver/CaseOutput.hpp"
#include "driver/FluidSetup.hpp"
#include "driver/FunctionObjectSchedule.hpp"
#include "driver/OutOfDomain.hpp"
#include "driver/Progress.hpp"
#include "driver/RestartState.hpp"
#include "driver/RunControls.hpp"
#include "driver/StopRequest.hpp"
#include "driver/Threads.hpp"
#include "io/ParticleState.hpp"
#include "io/TimeName.hpp"
#include "physics/FluidSystem.hpp"
#include "timeIntegrators/TimeIntegrator.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace sph {

namespace {

// A step of at most the stable size, shortened to land on `target`. Returns the time reached
// and the step the integrator took (an adaptive one may take less than asked).
struct StepTaken {
    double time;
    double size;
};

// Sorts the fluid by cell every few steps, counted from the run's first step rather than this
// invocation's so that a restart sorts where the uninterrupted run did; shifts and wraps the
// particles after the step.
template <int D>
StepTaken advanceOneStep(CaseSetup<D>& setup, double t, long step, double target, double timeTolerance) {
    FluidSystem<D>& system = *setup.system;
    TimeIntegrator<D>& integrator = *setup.integrator;
    if (integrator.allowsReordering() && step % stepsBetweenCellSorts == 0) {
        system.sortFluidByCell();
        integrator.stateChangedOutside();
    }
    double dt = setup.fixedDeltaT > 0.0 ? setup.fixedDeltaT
                                        : std::min(system.stableTimeStep(setup.courant, !integrator.viscosityImplicit()), setup.maxDeltaT);
    if (t + dt > target - timeTolerance) dt = target - t;
    const double taken = integrator.step(system, t, dt);
    if (system.shiftsParticles()) {
        system.shiftParticles(taken);
        integrator.stateChangedOutside();
    }
    if (system.wrapPeriodic()) integrator.stateChangedOutside();
    return {(taken >= dt && t + dt > target - timeTolerance) ? target : t + taken, taken};
}

// From the start state to endTime, or to a stop signal (which writes the time reached).
template <int D>
RunCost timeLoop(const std::filesystem::path& caseDirectory, const TimeDirectory& start, CaseSetup<D>& setup, RunControls controls,
                 OutOfDomain outOfDomain, ControlDictWatcher& watcher, CaseOutput<D>& output, FunctionObjectSchedule<D>& functionObjects) {
    FluidSystem<D>& system = *setup.system;
    const double c0 = std::visit([](const auto& eos) { return eos.c0; }, system.models().eos);
    const auto executeFunctionObjects = [&](double t, bool force) {
        auto timer = system.timers.time(Stage::FunctionObjects);
        functionObjects.execute(system.view(), t, force);
    };
    fmt::print("\nStarting time loop at t = {:g} (from {}), endTime {:g}, writeInterval {:g}\n\n", setup.header.time, start.path.string(),
               controls.endTime, controls.writeInterval);
    // The exact time from the state file: a directory name holds only its first digits.
    double t = setup.header.time;
    long step = setup.header.step;
    restoreRestartState(system, *setup.integrator, setup.integratorType, setup.header, t, stateFile(start.path, "fluid").string());
    executeFunctionObjects(t, true);
    Progress progress(t, controls.endTime, system.fluid.size());
    double nextWrite = controls.nextWriteAfter(t);
    const long firstStep = step;
    const StopRequest stopRequest;
    std::int64_t removedSoFar = 0;
    while (true) {
        const double timeTolerance = 1e-9 * controls.writeInterval;
        if (t >= controls.endTime - timeTolerance) break;
        // Land on write times and on endTime exactly.
        const StepTaken taken = advanceOneStep(setup, t, step, std::min(nextWrite, controls.endTime), timeTolerance);
        t = taken.time;
        ++step;
        if (outOfDomain == OutOfDomain::Remove) {
            if (const std::vector<std::uint32_t> outside = fluidOutside(system.fluid, system.domainMin(), system.domainMax()); !outside.empty()) {
                removeFluid(system.fluid, outside);
                setup.integrator->particlesMigrated();
                removedSoFar += static_cast<std::int64_t>(outside.size());
                reportRemoved(step, t, static_cast<std::int64_t>(outside.size()), removedSoFar);
            }
        }
        checkFluidState(system.fluid, system.domainMin(), system.domainMax(), {c0, setup.rho0}, step, t);
        const bool last = t >= controls.endTime - timeTolerance;
        if (const int signal = stopRequest.signal(); signal != 0 && !last) {
            executeFunctionObjects(t, true);
            output.writeTime(t, step);
            progress.finish();
            fmt::print("\n{} received: stopped at step {}, t = {:.9g}, and wrote the state to {}; rerun to continue from it\n", signalName(signal),
                       step, t, (caseDirectory / timeName(t)).string());
            break;
        }
        executeFunctionObjects(t, last);
        if (t >= nextWrite - timeTolerance || last) {
            output.writeTime(t, step);
            nextWrite = controls.nextWriteAfter(t);
        }
        progress.update(step, t, taken.size);
        if (const auto changed = watcher.changed(controls, t)) {
            controls = *changed;
            nextWrite = controls.nextWriteAfter(t);
            progress.setEndTime(controls.endTime);
        }
    }
    progress.finish();
    return {progress.elapsedSeconds(), system.fluid.size(), step - firstStep, t};
}

// The run's closing report: particle-steps/s, the integrator's counters, the time per stage.
template <int D>
void printRunReport(const FluidSystem<D>& system, const TimeIntegrator<D>& integrator, const RunCost& cost) {
    const double wall = cost.wallSeconds;
    const double particleSteps = static_cast<double>(cost.steps) * static_cast<double>(system.fluid.size());
    fmt::print("\nEnd at t = {:g}: {} steps, {} fluid + {} wall particles\n", cost.endTime, cost.steps, system.fluid.size(), system.walls.size());
    fmt::print("Wall time {:.2f} s, {:.3g} particle-steps/s\n", wall, wall > 0.0 ? particleSteps / wall : 0.0);
    fmt::print("{}", integrator.countersReport());
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
}

template <int D>
void run(const std::filesystem::path& caseDirectory, const Dictionary& controlDict, const TimeDirectory& start, RunMode mode,
         std::optional<int> threads) {
    CaseSetup<D> setup = setUpCase<D>(caseDirectory, start);
    FluidSystem<D>& system = *setup.system;
    const RunThreads runThreads(system.fluid.size() + system.walls.size(), D, threads);
    const double startTime = setup.header.time;

    const RunControls controls = RunControls::read(controlDict);
    const bool writeCsv = controlDict.getOrDefault("writeCsv", false);
    const OutOfDomain outOfDomain = readOutOfDomain(controlDict);
    ControlDictWatcher watcher(caseDirectory / "system/controlDict", controlDict.getOrDefault("runTimeModifiable", true));
    if (mode == RunMode::TimeLoop && !(controls.endTime > startTime))
        controlDict.fail("endTime", fmt::format("must be later than the start time {:g}, found {:g}", startTime, controls.endTime));
    for (const Patch<D>& patch : system.patches)
        if (patch.motion) patch.motion->checkCovers(startTime, controls.endTime);
    FunctionObjectSchedule<D> functionObjects(controlDict, caseDirectory, startTime, setup.rho0, system.view(),
                                              [&system](std::size_t patch) { system.patches[patch].recordsLoad = true; });
    controlDict.checkUnused();
    for (const Dictionary& dict : setup.dictionaries) dict.checkUnused();

    CaseOutput<D> output(caseDirectory, start, setup, writeCsv);
    if (mode == RunMode::RatesOnly) {
        system.evaluateRates(startTime);
        output.writeRates(startTime);
        return;
    }
    const RunCost cost = timeLoop(caseDirectory, start, setup, controls, outOfDomain, watcher, output, functionObjects);
    printRunReport(system, *setup.integrator, cost);
    functionObjects.reportErrorAgainstCost(caseDirectory, startTime, cost);
}

}  // namespace

TimeDirectory prepareStartTime(const std::filesystem::path& caseDirectory, const Dictionary& controlDict, RunMode mode, bool overwriteLaterTimes) {
    if (mode == RunMode::TimeLoop) removeIncompleteOutput(caseDirectory);
    const TimeDirectory start = selectStartTime(caseDirectory, controlDict);
    if (const std::vector<TimeDirectory> later = timesAfter(caseDirectory, start.time); mode == RunMode::TimeLoop && !later.empty()) {
        if (!overwriteLaterTimes) {
            std::string names;
            for (const TimeDirectory& t : later) (names += ' ') += t.path.filename().string();
            controlDict.fail("startFrom", fmt::format("the run starts at t = {:g}, but the case has later times (written by an earlier run):{}; "
                                                      "the run would overwrite them. Start from latestTime, remove them, or run wcsph "
                                                      "-overwrite to have them removed",
                                                      start.time, names));
        }
        removeTimeDirectories(later);
    }
    return start;
}

Dictionary readControlDict(const std::filesystem::path& caseDirectory) {
    if (!std::filesystem::is_directory(caseDirectory)) throw FatalError("error: case directory '" + caseDirectory.string() + "' does not exist");
    Dictionary controlDict = readCaseDictionary(caseDirectory, "system/controlDict");
    controlDict.findEntry("application");  // informational, as in OpenFOAM
    return controlDict;
}

void runCase(const std::filesystem::path& caseDirectory, RunMode mode, bool overwriteLaterTimes, std::optional<int> threads) {
    const Dictionary controlDict = readControlDict(caseDirectory);
    const TimeDirectory start = prepareStartTime(caseDirectory, controlDict, mode, overwriteLaterTimes);
    const int dimension = readStateHeader(stateFile(start.path, "fluid")).dimension;
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
                                 stateFile(start.path, "fluid").string(), dimension));
}

}  // namespace sph
