#include "parallel/ParallelRun.hpp"

#include "core/FatalError.hpp"
#include "driver/BlowUpCheck.hpp"
#include "driver/FluidSetup.hpp"
#include "driver/FunctionObjectSchedule.hpp"
#include "driver/OutOfDomain.hpp"
#include "driver/Progress.hpp"
#include "driver/RestartState.hpp"
#include "driver/RunControls.hpp"
#include "driver/StopRequest.hpp"
#include "driver/Threads.hpp"
#include "io/AtomicFile.hpp"
#include "io/ParticleCsv.hpp"
#include "io/PvdCollection.hpp"
#include "io/ParticleState.hpp"
#include "io/TimeName.hpp"
#include "parallel/CostBalance.hpp"
#include "parallel/DistributedSystem.hpp"
#include "parallel/ReductionsOverRanks.hpp"
#include "parallel/GatheredParticles.hpp"
#include "parallel/ParticlePieces.hpp"
#include "parallel/ShareOfCase.hpp"

#include <fmt/format.h>

#include <sys/resource.h>

#include <array>
#include <chrono>
#include <limits>

namespace sph::parallel {

namespace {

// A directory every rank writes into: rank 0 makes it under a temporary name and moves it into
// place once all have written, so that a reader sees no directory or the complete one.
template <class Write>
void writeDirectoryTogether(const Communicator& ranks, const std::filesystem::path& directory, Write&& write) {
    std::filesystem::path temporary;
    together(ranks, [&] {
        if (ranks.rank() == 0) temporary = temporaryDirectoryFor(directory);
    });
    temporary = ranks.broadcastFromFirst(temporary.string());
    try {
        write(temporary);
    } catch (const FatalError& error) {
        if (ranks.rank() == 0) abandonDirectory(temporary, directory, error);
        throw;
    }
    together(ranks, [&] {
        if (ranks.rank() == 0) moveDirectoryIntoPlace(temporary, directory);
    });
}

template <int D>
void writeState(const Communicator& ranks, const std::filesystem::path& directory, const DistributedSystem<D>& shared, StateHeader header,
                const CaseSetup<D>& setup) {
    writeParticlePieces(ranks, directory, "fluid", shared.heldFluid(), header, shared.ownedFluidPlaces());
    header.patchNames = setup.patchNames;
    header.patchLayers = setup.patchLayers;
    writeParticlePieces(ranks, directory, "walls", shared.heldWalls(), header, shared.ownedWallPlaces());
}

// Collective. fluid.csv and walls.csv as the serial run writes them: every rank's owned particles
// gathered on rank 0, in the serial order.
template <int D>
void writeGatheredCsv(const Communicator& ranks, const std::filesystem::path& directory, const DistributedSystem<D>& shared) {
    const auto write = [&](const char* name, ParticleSet<D> set) {
        gatherToFirst(ranks, set);
        together(ranks, [&] {
            if (ranks.rank() != 0) return;
            set.remove(fields::orderCell);  // the pieces' own
            set.remove(fields::orderRank);
            writeParticleCsv(directory / name, set);
        });
    };
    write("fluid.csv", shared.ownedFluid());
    write("walls.csv", shared.ownedWalls());
}

// What the ranks agree on after each step: every entry the largest any rank reported.
struct StepAgreement {
    double nextStep;      // the stable size of the next step
    double displacement;  // since the halos were built
    bool blownUp;
    int signal;
    bool functionObjectsDue;
    std::optional<RunControls> changedControls;  // rank 0's reading of controlDict
};

template <int D>
StepAgreement agreeAfterStep(const Communicator& ranks, const CaseSetup<D>& setup, const DistributedSystem<D>& shared, bool blownUp,
                             const StopRequest& stopRequest, ControlDictWatcher& watcher, const RunControls& controls,
                             const FunctionObjectSchedule<D>& functionObjects, double t) {
    const FluidSystem<D>& system = *setup.system;
    const double stable = setup.fixedDeltaT > 0.0
                              ? setup.fixedDeltaT
                              : std::min(system.stableTimeStep(setup.courant, !setup.integrator->viscosityImplicit()), setup.maxDeltaT);
    constexpr double none = std::numeric_limits<double>::lowest();
    std::optional<RunControls> changed;
    if (ranks.rank() == 0) changed = watcher.changed(controls, t);
    std::array<double, 7> values{-stable,
                                 shared.largestDisplacement(),
                                 blownUp ? 1.0 : 0.0,
                                 static_cast<double>(stopRequest.signal()),
                                 functionObjects.dueAt(t) ? 1.0 : 0.0,
                                 changed ? changed->endTime : none,
                                 changed ? changed->writeInterval : none};
    ranks.maxOverRanks(values);
    StepAgreement agreed{-values[0], values[1], values[2] > 0.0, static_cast<int>(values[3]), values[4] > 0.0, std::nullopt};
    if (values[5] != none) agreed.changedControls = RunControls{values[5], values[6]};
    return agreed;
}

// The seconds of a rank's own work: the stages of the evaluation and the step, not the waits for
// the other ranks (halo builds and refreshes, the step agreement) nor rank 0's output.
double workSeconds(const StageTimers& timers) {
    double seconds = 0.0;
    for (const Stage stage : {Stage::Neighbours, Stage::Density, Stage::Boundary, Stage::Forces, Stage::Integrator, Stage::Shifting})
        seconds += timers.seconds(stage);
    return seconds;
}

// Where the time went, every rank's parts side by side as the largest and the smallest over the
// ranks: the stages of the serial report, then what the decomposition adds: the halo builds
// (migrations and repartitions), the halo refreshes and the once-per-step agreement, where a rank
// waits for the slowest. Then each rank's peak memory (resident set, as the kernel counts it).
template <int D>
void printTimePerPart(const Communicator& ranks, const FluidSystem<D>& system, const DistributedSystem<D>& shared, double buildSeconds,
                      double agreementSeconds, double wall) {
    constexpr std::size_t stages = static_cast<std::size_t>(Stage::Count);
    constexpr std::array<std::string_view, 3> sharing{"halo builds", "halo refreshes", "step agreement"};
    std::array<double, stages + sharing.size() + 1> largest{}, smallest{};
    for (std::size_t s = 0; s < stages; ++s) largest[s] = system.timers.seconds(static_cast<Stage>(s));
    largest[stages] = buildSeconds;
    largest[stages + 1] = shared.exchangeSeconds();
    largest[stages + 2] = agreementSeconds;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    largest.back() = static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
    for (std::size_t s = 0; s < largest.size(); ++s) smallest[s] = -largest[s];
    ranks.maxOverRanks(largest);
    ranks.maxOverRanks(smallest);
    fmt::print("Time per part, largest and smallest over the ranks:\n");
    for (std::size_t s = 0; s + 1 < largest.size(); ++s) {
        const std::string_view name = s < stages ? stageNames[s] : sharing[s - stages];
        fmt::print("    {:<20} {:8.3f} s  {:5.1f} %   {:8.3f} s\n", name, largest[s], wall > 0.0 ? 100.0 * largest[s] / wall : 0.0, -smallest[s]);
    }
    fmt::print("Peak memory of a rank: largest {:.1f} MiB, smallest {:.1f} MiB\n", largest.back(), -smallest.back());
}

template <int D>
void writeRates(const Communicator& ranks, const std::filesystem::path& caseDirectory, CaseSetup<D>& setup, const DistributedSystem<D>& shared) {
    const double t = setup.header.time;
    setup.system->evaluateRates(t);
    const std::filesystem::path directory = caseDirectory / "postProcessing" / "rates" / timeName(t);
    together(ranks, [&] {
        if (ranks.rank() == 0) std::filesystem::create_directories(directory.parent_path());
    });
    writeDirectoryTogether(ranks, directory, [&](const std::filesystem::path& temporary) {
        writeState(ranks, temporary, shared, setup.header, setup);
        writeGatheredCsv(ranks, temporary, shared);
    });
    fmt::print("\nWrote the right-hand side at t = {:g} on {} ranks to {} (fluid.pvtu, walls.pvtu and .csv)\n", t, ranks.size(), directory.string());
}

template <int D>
void timeLoop(const Communicator& ranks, const std::filesystem::path& caseDirectory, const TimeDirectory& start, CaseSetup<D>& setup,
              DistributedSystem<D>& shared, RunControls controls, OutOfDomain outOfDomain, ControlDictWatcher& watcher,
              FunctionObjectSchedule<D>& functionObjects, bool writeCsv, double balanceThreshold) {
    FluidSystem<D>& system = *setup.system;
    TimeIntegrator<D>& integrator = *setup.integrator;
    const double c0 = std::visit([](const auto& eos) { return eos.c0; }, system.models().eos);
    const auto executeFunctionObjects = [&](double t, bool force) {
        auto timer = system.timers.time(Stage::FunctionObjects);
        functionObjects.execute(shared.view(), t, force);
    };
    const auto fluidParticles = static_cast<std::size_t>(ranks.sumOverRanks(static_cast<std::int64_t>(shared.ownedFluidCount())));

    PvdCollection pvd(caseDirectory / (caseName(caseDirectory) + ".pvd"));
    for (const TimeDirectory& written : findTimeDirectories(caseDirectory))
        if (written.time <= start.time) pvd.add(written.time, stateFilesOf(written));
    StateHeader header = setup.header;
    const auto writeTime = [&](double t, long step) {
        auto timer = system.timers.time(Stage::Output);
        header.time = t;
        header.step = step;
        collectRestartState(system, integrator, setup.integratorType, header);
        const std::string name = timeName(t);
        writeDirectoryTogether(ranks, caseDirectory / name, [&](const std::filesystem::path& temporary) {
            writeState(ranks, temporary, shared, header, setup);
            if (writeCsv) writeGatheredCsv(ranks, temporary, shared);
        });
        if (ranks.rank() == 0) pvd.add(t, {name + "/fluid.pvtu", name + "/walls.pvtu"});
    };

    fmt::print("\nStarting time loop at t = {:g} (from {}) on {} ranks, endTime {:g}, writeInterval {:g}\n\n", setup.header.time, start.path.string(),
               ranks.size(), controls.endTime, controls.writeInterval);
    double t = setup.header.time;
    long step = setup.header.step;
    restoreRestartState(system, integrator, setup.integratorType, setup.header, t, stateFile(start.path, "fluid").string());
    executeFunctionObjects(t, true);
    for (const Patch<D>& patch : system.patches)
        if (patch.motion) patch.motion->checkCovers(setup.header.time, controls.endTime);
    const StopRequest stopRequest;
    double agreementSeconds = 0.0;
    const auto agree = [&](bool blownUp) {
        const auto begin = std::chrono::steady_clock::now();
        const StepAgreement agreement = agreeAfterStep(ranks, setup, shared, blownUp, stopRequest, watcher, controls, functionObjects, t);
        agreementSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        return agreement;
    };
    StepAgreement agreed = agree(false);
    Progress progress(t, controls.endTime, fluidParticles);
    double nextWrite = controls.nextWriteAfter(t);
    const long firstStep = step;
    CostBalance balance(balanceThreshold, step);
    double buildSeconds = 0.0;
    std::int64_t removedSoFar = 0;
    while (true) {
        const double timeTolerance = 1e-9 * controls.writeInterval;
        if (t >= controls.endTime - timeTolerance) break;
        const bool sortByCell = integrator.allowsReordering() && step % stepsBetweenCellSorts == 0;
        if (sortByCell || agreed.displacement > 0.25 * shared.skin()) {
            const auto begin = std::chrono::steady_clock::now();
            const auto repartition = sortByCell ? balance.check(ranks, step, workSeconds(system.timers), shared.ownedWeight()) : std::nullopt;
            // The SUNDIALS integrators restart where the serial run restarts (at the sort) and
            // take the new particles where those a rank owns changed: their vector holds them.
            bool ownedChanged = true;
            if (repartition) {
                shared.repartition(repartition->weightPerParticle);
                fmt::print("Repartitioned at step {}: the slowest rank's work was {:.3f} times the mean\n", step, repartition->imbalance);
            } else {
                ownedChanged = shared.redistribute(sortByCell);
            }
            if (sortByCell)
                integrator.stateChangedOutside();
            else if (ownedChanged)
                integrator.particlesMigrated();
            buildSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        }
        const double target = std::min(nextWrite, controls.endTime);
        const double dt = t + agreed.nextStep > target - timeTolerance ? target - t : agreed.nextStep;
        const double taken = integrator.step(system, t, dt);
        if (system.shiftsParticles()) {
            system.shiftParticles(taken);
            shared.refreshShifted();
            integrator.stateChangedOutside();
        }
        if (system.wrapPeriodic()) integrator.stateChangedOutside();
        t = (taken >= dt && t + dt > target - timeTolerance) ? target : t + taken;
        ++step;

        // Particles that left the domain go where the serial run's go, before the check: at once
        // (a collective decision, then the halos built again without them).
        if (outOfDomain == OutOfDomain::Remove) {
            const std::vector<std::uint32_t> outside = fluidOutside(system.fluid, system.domainMin(), system.domainMax());
            if (const std::int64_t removed = ranks.sumOverRanks(static_cast<std::int64_t>(shared.giveUpOwnedFluid(outside))); removed > 0) {
                (void)shared.redistribute(false);
                integrator.particlesMigrated();
                removedSoFar += removed;
                reportRemoved(step, t, removed, removedSoFar);
            }
        }
        std::optional<std::string> blowUp;
        try {
            checkFluidState(system.fluid, system.domainMin(), system.domainMax(), {c0, setup.rho0}, step, t);
        } catch (const FatalError& e) {
            blowUp = e.what();
        }
        agreed = agree(blowUp.has_value());
        if (agreed.blownUp) ranks.stopIfAnyFailed(blowUp);
        if (agreed.displacement > 0.5 * shared.skin())
            throw FatalError(
                fmt::format("error: at step {}, t = {:.9g}, a particle moved {:.3g} m since the halos were built, past the {:.3g} m "
                            "the decomposed run allows between two builds; the step is too long for wcsph -parallel",
                            step, t, agreed.displacement, 0.5 * shared.skin()));
        const bool last = t >= controls.endTime - timeTolerance;
        if (agreed.signal != 0 && !last) {
            executeFunctionObjects(t, true);
            writeTime(t, step);
            progress.finish();
            fmt::print("\n{} received: stopped at step {}, t = {:.9g}, and wrote the state to {}\n", signalName(agreed.signal), step, t,
                       (caseDirectory / timeName(t)).string());
            break;
        }
        if (agreed.functionObjectsDue || last) executeFunctionObjects(t, last);
        if (t >= nextWrite - timeTolerance || last) {
            writeTime(t, step);
            nextWrite = controls.nextWriteAfter(t);
        }
        progress.update(step, t, taken);
        if (agreed.changedControls) {
            controls = *agreed.changedControls;
            nextWrite = controls.nextWriteAfter(t);
            progress.setEndTime(controls.endTime);
        }
    }
    progress.finish();
    const double wall = progress.elapsedSeconds();
    const double particleSteps = static_cast<double>(step - firstStep) * static_cast<double>(fluidParticles);
    fmt::print("\nEnd at t = {:g}: {} steps, {} fluid particles on {} ranks\n", t, step - firstStep, fluidParticles, ranks.size());
    fmt::print("Wall time {:.2f} s, {:.3g} particle-steps/s\n", wall, wall > 0.0 ? particleSteps / wall : 0.0);
    fmt::print("{}", integrator.countersReport());
    printTimePerPart(ranks, system, shared, buildSeconds, agreementSeconds, wall);
    functionObjects.reportErrorAgainstCost(caseDirectory, setup.header.time, {wall, fluidParticles, step - firstStep, t});
}

template <int D>
void runOfDimension(const Communicator& ranks, const std::filesystem::path& caseDirectory, const Dictionary& controlDict, const TimeDirectory& start,
                    RunMode mode, std::optional<int> threads, double balanceThreshold) {
    CaseSetup<D> setup = setUpShareOfCase<D>(ranks, caseDirectory, start);
    for (const Dictionary& dict : setup.dictionaries) dict.checkUnused();
    std::optional<RunControls> controls;
    std::optional<ControlDictWatcher> watcher;
    bool writeCsv = false;
    OutOfDomain outOfDomain = OutOfDomain::Stop;
    if (mode == RunMode::TimeLoop) {
        outOfDomain = readOutOfDomain(controlDict);
        controls = RunControls::read(controlDict);
        if (!(controls->endTime > setup.header.time))
            controlDict.fail("endTime", fmt::format("must be later than the start time {:g}, found {:g}", setup.header.time, controls->endTime));
        writeCsv = controlDict.getOrDefault("writeCsv", false);
        const bool modifiable = controlDict.getOrDefault("runTimeModifiable", true);
        // Rank 0 alone reads a changed controlDict; the others take its values.
        watcher.emplace(caseDirectory / "system/controlDict", modifiable && ranks.rank() == 0);
    }
    FluidSystem<D>& system = *setup.system;
    DistributedSystem<D> shared(ranks, system);
    const RunThreads runThreads(system.fluid.size() + system.walls.size(), D, threads);
    if (mode == RunMode::RatesOnly) return writeRates(ranks, caseDirectory, setup, shared);
    // Every rank selects the function objects, on its share; they combine over the ranks.
    const ReductionsOverRanks reductions(ranks);
    FunctionObjectSchedule<D> functionObjects(
        controlDict, caseDirectory, setup.header.time, setup.rho0, shared.view(),
        [&setup](std::size_t patch) { setup.system->patches[patch].recordsLoad = true; }, reductions);
    together(ranks, [&] { controlDict.checkUnused(); });
    timeLoop(ranks, caseDirectory, start, setup, shared, *controls, outOfDomain, *watcher, functionObjects, writeCsv, balanceThreshold);
}

}  // namespace

void runCaseInParallel(const Communicator& ranks, const std::filesystem::path& caseDirectory, RunMode mode, bool overwriteLaterTimes,
                       std::optional<int> threads, double balanceThreshold) {
    const Dictionary controlDict = readControlDict(caseDirectory);
    // Rank 0 alone removes files; the others wait for it, then find the same start.
    together(ranks, [&] {
        if (ranks.rank() == 0) prepareStartTime(caseDirectory, controlDict, mode, overwriteLaterTimes);
    });
    const TimeDirectory start = selectStartTime(caseDirectory, controlDict);
    const int dimension = readStateHeader(stateFile(start.path, "fluid")).dimension;
#ifdef SPHKIT_HAS_2D
    if (dimension == 2) return runOfDimension<2>(ranks, caseDirectory, controlDict, start, mode, threads, balanceThreshold);
#endif
#ifdef SPHKIT_HAS_3D
    if (dimension == 3) return runOfDimension<3>(ranks, caseDirectory, controlDict, start, mode, threads, balanceThreshold);
#endif
    throw FatalError(fmt::format("error: wcsph -parallel runs the 2D and 3D cases this build compiled, and '{}' is {}D",
                                 stateFile(start.path, "fluid").string(), dimension));
}

}  // namespace sph::parallel
