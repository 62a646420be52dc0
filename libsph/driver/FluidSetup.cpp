#include "driver/FluidSetup.hpp"

#include "io/ParticleState.hpp"
#include "io/SelectByType.hpp"
#include "physics/FluidProperties.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <cmath>
#include <limits>
#include <map>

namespace sph {

namespace {

DensityFormulation selectDensity(const Dictionary& dict) {
    static const std::map<std::string, DensityFormulation> formulations{{"continuity", DensityFormulation::Continuity},
                                                                        {"summation", DensityFormulation::Summation}};
    const std::string name = dict.get<std::string>("type");
    const auto it = formulations.find(name);
    if (it == formulations.end())
        throw FatalError(dict.entry("type").tokens().front().where,
                         "unknown density formulation '" + name + "'; valid density formulation names are:\n    continuity\n    summation");
    return it->second;
}

template <int D>
void requireFields(const ParticleSet<D>& set, const std::filesystem::path& file, std::initializer_list<ScalarField> scalars,
                   std::initializer_list<VectorField> vectors, std::initializer_list<IntegerField> integers) {
    const auto require = [&](auto field) {
        if (!set.has(field))
            throw FatalError("error: particle file '" + file.string() + "' lacks the field '" + std::string(field.name) +
                             "' (regenerate it with generateParticles)");
    };
    for (auto field : scalars) require(field);
    for (auto field : vectors) require(field);
    for (auto field : integers) require(field);
}

// A corrupt or hand-edited state: every value must be a finite number, masses and densities positive.
template <int D>
void requireValidValues(const ParticleSet<D>& set, const std::filesystem::path& file) {
    const auto reject = [&](std::size_t i, const std::string& what) {
        throw FatalError(
            fmt::format("error: particle file '{}': particle id {} has {} (a corrupt state file?)", file.string(), set.globalId[i], what));
    };
    for (std::size_t i = 0; i < set.size(); ++i)
        if (!set.position[i].allFinite()) reject(i, "a non-finite position");
    for (const auto& [name, field] : set.scalars())
        for (std::size_t i = 0; i < field.values.size(); ++i) {
            if (!std::isfinite(field.values[i])) reject(i, fmt::format("a non-finite {}", name));
            if ((name == fields::mass.name || name == fields::density.name) && !(field.values[i] > 0.0))
                reject(i, fmt::format("{} {:g}, not positive", name, field.values[i]));
            if (name == fields::area.name && field.values[i] < 0.0) reject(i, fmt::format("area {:g}, negative", field.values[i]));
        }
    for (const auto& [name, field] : set.vectors())
        for (std::size_t i = 0; i < field.values.size(); ++i)
            if (!field.values[i].allFinite()) reject(i, fmt::format("a non-finite {}", name));
}

// Two particles with one id (a restart would mix up their histories) or two fluid particles at
// one position (their pair has no direction). Wall particles may coincide: patches that meet
// share a corner.
template <int D>
void requireDistinctParticles(const ParticleSet<D>& set, const std::filesystem::path& file, bool checkPositions) {
    const auto reject = [&](const std::string& what) {
        throw FatalError(fmt::format("error: particle file '{}': {} (a corrupt or hand-edited state file?)", file.string(), what));
    };
    std::vector<std::size_t> order(set.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return set.globalId[a] < set.globalId[b]; });
    for (std::size_t k = 1; k < order.size(); ++k)
        if (set.globalId[order[k]] == set.globalId[order[k - 1]])
            reject(fmt::format("particles {} and {} (in file order) have the same id {}", order[k - 1], order[k], set.globalId[order[k]]));
    const auto lexicographic = [&](std::size_t a, std::size_t b) {
        return std::lexicographical_compare(set.position[a].data(), set.position[a].data() + D, set.position[b].data(), set.position[b].data() + D);
    };
    if (checkPositions) std::sort(order.begin(), order.end(), lexicographic);
    for (std::size_t k = 1; checkPositions && k < order.size(); ++k)
        if (set.position[order[k]] == set.position[order[k - 1]])
            reject(fmt::format("particle ids {} and {} are at the same position ({:g})", set.globalId[order[k - 1]], set.globalId[order[k]],
                               fmt::join(set.position[order[k]].data(), set.position[order[k]].data() + D, " ")));
}

// Wall normals of unit length (a zero normal leaves the wall without a side).
template <int D>
void requireUnitNormals(const ParticleSet<D>& set, const std::filesystem::path& file) {
    if (!set.has(fields::normal)) return;
    const auto& normal = set[fields::normal];
    for (std::size_t i = 0; i < set.size(); ++i)
        if (std::abs(normal[i].norm() - 1.0) > 1e-3)
            throw FatalError(
                fmt::format("error: particle file '{}': wall particle id {} has the normal ({:g}) of length {:g} (valid: a "
                            "unit vector) (a corrupt or hand-edited state file?)",
                            file.string(), set.globalId[i], fmt::join(normal[i].data(), normal[i].data() + D, " "), normal[i].norm()));
}

// Each patch's layers of wall particles against what its model needs: the wall field `layer`
// counted, or the generator's record (`patchLayers`) where it is more (a solid whose layers from
// opposite faces meet inside it holds, behind each face, more than any particle's own count).
template <int D>
void requireWallLayout(const ParticleSet<D>& walls, const Dictionary& boundaryDict, const std::vector<std::string>& patchNames,
                       const std::vector<double>& patchLayers, const std::vector<std::unique_ptr<BoundaryModel<D>>>& models, double support,
                       double dx, const StateShare<D>* share) {
    if (!walls.has(fields::layer)) return;
    std::vector<double> layerCounts(patchNames.size(), 0.0);
    const auto& patch = walls[fields::patch];
    const auto& layer = walls[fields::layer];
    for (std::size_t w = 0; w < walls.size(); ++w) {
        double& most = layerCounts[static_cast<std::size_t>(patch[w])];
        most = std::max(most, layer[w] + 1.0);
    }
    if (share) share->largestOverRanks(layerCounts);
    if (patchLayers.size() == patchNames.size())
        for (std::size_t p = 0; p < patchNames.size(); ++p) layerCounts[p] = std::max(layerCounts[p], patchLayers[p]);
    const std::vector<int> layers(layerCounts.begin(), layerCounts.end());
    for (std::size_t p = 0; p < patchNames.size(); ++p) {
        const Dictionary& patchDict = boundaryDict.subDict(patchNames[p]);
        const std::string type = patchDict.get<std::string>("type");
        const int needed = models[p]->minimumLayers(support, dx);
        if (!models[p]->actsThroughWallParticles() && layers[p] > 1)
            patchDict.fail("type",
                           fmt::format("'{}' acts from one layer of wall particles on the wall surface, but patch '{}' has {} layers; "
                                       "generate it with layers 1; firstLayerOffset 0; in system/generateParticlesDict, or with no layers there (the "
                                       "generator then takes them from the model)",
                                       type, patchNames[p], layers[p]));
        if (layers[p] < needed)
            patchDict.fail(
                "type", fmt::format("'{}' needs at least {} layers of wall particles to fill the kernel support ({:g} = {:g} dx) behind "
                                    "the wall, but patch '{}' has {}; generate it with layers {}; in system/generateParticlesDict (or with no layers "
                                    "there: the generator then takes them from the model; a solid thinner than its layers holds fewer, as "
                                    "generateParticles notes), or choose a wall-force model (deficiencyCorrection) on one layer",
                                    type, needed, support, support / dx, patchNames[p], layers[p], needed));
    }
}

// Checks of the particles this run holds; with a share, a failure on one rank stops every rank
// (what comes next involves them all).
template <int D>
void checkOnEveryRank(const StateShare<D>* share, const std::function<void()>& checks) {
    share ? share->checkOnEveryRank(checks) : checks();
}

// The particle state of the start time, checked: fields, values, distinct particles, inside the domain.
template <int D>
struct StartState {
    ParticleSet<D> fluid{"fluid"}, walls{"walls"};
    StateHeader wallHeader;
    Vec<D> domainMin, domainMax;
    std::array<bool, D> periodic{};
};

template <int D>
StartState<D> readStartState(const TimeDirectory& start, StateHeader& header, const StateShare<D>* share) {
    StartState<D> state;
    const auto fluidFile = stateFile(start.path, "fluid");
    const auto wallFile = stateFile(start.path, "walls");
    state.fluid = share ? share->read(fluidFile, "fluid", header) : readParticleState<D>(fluidFile, "fluid", header);
    state.walls = share ? share->read(wallFile, "walls", state.wallHeader) : readParticleState<D>(wallFile, "walls", state.wallHeader);
    for (int d = 0; d < D; ++d) {
        state.domainMin[d] = header.domainMin[static_cast<std::size_t>(d)];
        state.domainMax[d] = header.domainMax[static_cast<std::size_t>(d)];
    }
    checkOnEveryRank(share, [&] {
        requireFields(state.fluid, fluidFile, {fields::density, fields::mass}, {fields::velocity}, {});
        requireFields(state.walls, wallFile, {fields::mass, fields::spacing}, {fields::normal}, {fields::patch});
        requireValidValues(state.fluid, fluidFile);
        requireValidValues(state.walls, wallFile);
        requireUnitNormals(state.walls, wallFile);
        const ParticleSet<D>& fluid = state.fluid;
        for (std::size_t i = 0; i < fluid.size(); ++i)
            if ((fluid.position[i].array() < state.domainMin.array()).any() || (fluid.position[i].array() > state.domainMax.array()).any())
                throw FatalError(fmt::format("error: '{}': fluid particle id {} at ({:g}) lies outside the domain [({:g}), ({:g})]",
                                             fluidFile.string(), fluid.globalId[i], fmt::join(fluid.position[i], " "),
                                             fmt::join(state.domainMin, " "), fmt::join(state.domainMax, " ")));
    });
    const auto requireDistinct = [&](const ParticleSet<D>& set, const std::filesystem::path& file, bool checkPositions) {
        share ? share->requireDistinct(set, file, checkPositions) : requireDistinctParticles(set, file, checkPositions);
    };
    requireDistinct(state.fluid, fluidFile, true);
    requireDistinct(state.walls, wallFile, false);
    std::array<double, 1> fluidCount{static_cast<double>(state.fluid.size())};
    if (share) share->largestOverRanks(fluidCount);
    if (fluidCount[0] == 0.0)
        throw FatalError("error: '" + fluidFile.string() + "' holds no fluid particles; check the fluid regions in system/generateParticlesDict");
    if (!(header.spacing > 0.0))
        throw FatalError(fmt::format("error: '{}': particle spacing must be positive, found {:g}", fluidFile.string(), header.spacing));
    for (std::size_t d = 0; d < header.periodic.size() && d < static_cast<std::size_t>(D); ++d) state.periodic[d] = header.periodic[d] != 0.0;
    return state;
}

// The kernel from system/sphSchemes, with h = hdx dx.
template <int D>
Kernel<D> selectKernel(const Dictionary& schemes, double dx, double& h) {
    const Dictionary& kernelDict = schemes.subDict("kernel");
    const double hdx = kernelDict.getPositive("hdx");
    if (hdx < 1.0) kernelDict.fail("hdx", fmt::format("h = hdx dx must not be smaller than the particle spacing; found hdx {:g} (valid: >= 1)", hdx));
    h = hdx * dx;
    Kernel<D> kernel = selectByType(makeKernelRegistry<D>(), kernelDict, h);
    if (!std::visit([](const auto& k) { return compiledKernel<std::decay_t<decltype(k)>>; }, kernel))
        kernelDict.fail("type", fmt::format("kernel '{}' is not compiled into this build (CMake option SPHKIT_KERNELS); compiled kernels: {}",
                                            kernelDict.get<std::string>("type"), compiledKernelNames));
    fmt::print("Selecting kernel {}: hdx {:g}, dx {:g}, h {:g}, support radius {:g}\n", kernelDict.get<std::string>("type"), hdx, dx, h,
               std::visit([](const auto& k) { return k.supportRadius(); }, kernel));
    return kernel;
}

// Density formulation, viscosity, density diffusion and particle shifting from system/sphSchemes.
template <int D>
FluidModels<D> selectFluidModels(const Dictionary& schemes, Kernel<D> kernel, const FluidProperties<D>& properties, const ModelContext& context) {
    const Dictionary& densityDict = schemes.subDict("density");
    const DensityFormulation density = selectDensity(densityDict);
    fmt::print("Selecting density {}\n", densityDict.get<std::string>("type"));
    const Dictionary& viscosityDict = schemes.subDict("viscosity");
    Viscosity viscosity = selectByType(makeViscosityRegistry(), viscosityDict, viscosityDict, context);
    fmt::print("Selecting viscosity {}\n", describe(viscosity));
    // Summation density has nothing to diffuse: there the keyword may be left out.
    const bool summation = density == DensityFormulation::Summation;
    const Dictionary* diffusionDict = summation ? schemes.findSubDict("densityDiffusion") : &schemes.subDict("densityDiffusion");
    DensityDiffusion<D> diffusion =
        diffusionDict ? selectByType(makeDensityDiffusionRegistry<D>(), *diffusionDict, *diffusionDict, context) : NoDensityDiffusion{};
    if (summation && !std::holds_alternative<NoDensityDiffusion>(diffusion))
        diffusionDict->fail("type", "density diffusion acts on the continuity equation; with summation density select 'none' or leave it out");
    fmt::print("Selecting densityDiffusion {}\n", describe<D>(diffusion));
    // Optional: a case that does not name it shifts nothing.
    const Dictionary* shiftingDict = schemes.findSubDict("particleShifting");
    const ParticleShifting shifting = shiftingDict ? selectByType(makeParticleShiftingRegistry(), *shiftingDict, *shiftingDict, context)
                                                   : ParticleShifting{NoShifting{}, {}, context.dx};
    if (shiftingDict) fmt::print("Selecting particleShifting {}\n", describe(shifting));
    return {std::move(kernel), properties.eos, std::move(viscosity), std::move(diffusion), density, shifting};
}

// One boundary model per patch named in the wall state, from constant/boundaryProperties; the
// walls sorted so that the wall-particle patches come first (they enter the kernel sums), then
// the wall-force patches.
template <int D>
std::vector<Patch<D>> selectPatches(const std::filesystem::path& caseDirectory, const Dictionary& boundaryDict, const std::filesystem::path& wallFile,
                                    ParticleSet<D>& walls, const std::vector<std::string>& patchNames, const std::vector<double>& patchLayers,
                                    const ModelContext& context, double support, const StateShare<D>* share) {
    const auto& patchOfWall = walls[fields::patch];
    checkOnEveryRank(share, [&] {
        for (int p : patchOfWall)
            if (p < 0 || static_cast<std::size_t>(p) >= patchNames.size())
                throw FatalError(fmt::format("error: '{}': wall patch index {} has no name in patchNames", wallFile.string(), p));
    });
    for (const std::string& keyword : boundaryDict.keywords()) {
        if (keyword == "FoamFile") continue;
        if (std::find(patchNames.begin(), patchNames.end(), keyword) == patchNames.end())
            throw FatalError(boundaryDict.entry(keyword).where(),
                             fmt::format("patch '{}' in constant/boundaryProperties is not a wall patch of the case; its patches are: {}", keyword,
                                         patchNames.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(patchNames, ", "))));
    }
    const auto boundaryRegistry = makeBoundaryModelRegistry<D>();
    std::vector<std::unique_ptr<BoundaryModel<D>>> boundaryModels;
    for (const std::string& name : patchNames) {
        const Dictionary& patchDict = boundaryDict.subDict(name);
        boundaryModels.push_back(selectByType(boundaryRegistry, patchDict, patchDict, context));
    }
    requireWallLayout(walls, boundaryDict, patchNames, patchLayers, boundaryModels, support, context.dx, share);
    const auto rank = [&](int patch) {
        return std::pair(boundaryModels[static_cast<std::size_t>(patch)]->actsThroughWallParticles() ? 0 : 1, patch);
    };
    std::vector<std::uint32_t> order(walls.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return rank(patchOfWall[a]) < rank(patchOfWall[b]); });
    walls.permute(order);
    std::vector<std::size_t> patchOrder(patchNames.size());
    for (std::size_t p = 0; p < patchOrder.size(); ++p) patchOrder[p] = p;
    std::stable_sort(patchOrder.begin(), patchOrder.end(),
                     [&](std::size_t a, std::size_t b) { return rank(static_cast<int>(a)) < rank(static_cast<int>(b)); });
    std::vector<Patch<D>> patches;
    const auto& sortedPatch = walls[fields::patch];
    std::size_t begin = 0;
    for (std::size_t p : patchOrder) {
        Patch<D> patch;
        patch.name = patchNames[p];
        patch.wallField = static_cast<int>(p);
        patch.begin = begin;
        patch.end = begin + static_cast<std::size_t>(std::count(sortedPatch.begin(), sortedPatch.end(), static_cast<int>(p)));
        begin = patch.end;
        patch.model = std::move(boundaryModels[p]);
        // A share's count is of the particles this rank read, not of those it will own: left out.
        const std::string count = share ? "" : fmt::format(" ({} particles)", patch.end - patch.begin);
        fmt::print("Selecting boundary model for patch {}{}: {}\n", patch.name, count, patch.model->describe());
        if (const Dictionary* motion = boundaryDict.subDict(patch.name).findSubDict("motion")) {
            patch.motion = selectByType(makePatchMotionRegistry<D>(), *motion, *motion, caseDirectory.string());
            fmt::print("Selecting motion for patch {}: {}\n", patch.name, patch.motion->describe());
            if (patch.motion->isFree() && patch.model->actsThroughWallParticles())
                motion->fail("type",
                             "a free body takes its loads from a wall-force model (monaghanKajtar, lennardJones, deficiencyCorrection, "
                             "deficiencyCorrectionBoundaryIntegral); patch '" +
                                 patch.name + "' uses " + patch.model->describe());
        }
        patches.push_back(std::move(patch));
    }
    return patches;
}

// The time integrator and the step's limits from system/timeIntegration.
template <int D>
void selectIntegrator(const Dictionary& timeIntegration, const Dictionary& schemes, bool shifts, CaseSetup<D>& setup) {
    const Dictionary& integratorDict = timeIntegration.subDict("integrator");
    setup.integrator = selectByType(makeTimeIntegratorRegistry<D>(), integratorDict, integratorDict);
    setup.integratorType = integratorDict.get<std::string>("type");
    setup.courant = timeIntegration.getPositiveOrDefault("courant", 0.2);
    if (setup.courant > 1.0)
        timeIntegration.fail("courant", fmt::format("must not exceed 1 (a step would let sound cross more than a smoothing length), found {:g}; "
                                                    "0.1 to 0.4 is stable for every integrator",
                                                    setup.courant));
    setup.maxDeltaT = timeIntegration.getPositiveOrDefault("maxDeltaT", std::numeric_limits<double>::infinity());
    setup.fixedDeltaT = timeIntegration.getPositiveOrDefault("fixedDeltaT", 0.0);
    if (shifts && !setup.integrator->allowsReordering())
        schemes.subDict("particleShifting")
            .fail("type", fmt::format("particle shifting moves the particles after every step, which the history of integrator '{}' "
                                      "cannot follow; select another integrator (system/timeIntegration) or particleShifting none",
                                      setup.integratorType));
    fmt::print("Selecting time integrator {}: courant {:g}{}{}\n", setup.integrator->describe(), setup.courant,
               std::isfinite(setup.maxDeltaT) ? fmt::format(", maxDeltaT {:g}", setup.maxDeltaT) : "",
               setup.fixedDeltaT > 0.0 ? fmt::format(", fixedDeltaT {:g}", setup.fixedDeltaT) : "");
}

}  // namespace

template <int D>
CaseSetup<D> setUpCase(const std::filesystem::path& caseDirectory, const TimeDirectory& start, const StateShare<D>* share) {
    CaseSetup<D> setup;
    Dictionary schemes = readCaseDictionary(caseDirectory, "system/sphSchemes");
    Dictionary timeIntegration = readCaseDictionary(caseDirectory, "system/timeIntegration");
    Dictionary fluidDict = readCaseDictionary(caseDirectory, "constant/fluidProperties");
    Dictionary boundaryDict = readCaseDictionary(caseDirectory, "constant/boundaryProperties");
    StartState<D> state = readStartState<D>(start, setup.header, share);
    const double dx = setup.header.spacing;

    const FluidProperties<D> properties = readFluidProperties<D>(fluidDict);
    setup.rho0 = properties.rho0;
    fmt::print("Selecting equationOfState {}\n", describe(properties.eos));
    fmt::print("Fluid: rho0 {:g}, nu {:g}, gravity ({:g}), gravityRampTime {:g}\n", properties.rho0, properties.nu,
               fmt::join(properties.gravity, " "), properties.gravityRampTime);
    double h = 0.0;
    Kernel<D> kernel = selectKernel<D>(schemes, dx, h);
    const double support = std::visit([](const auto& k) { return k.supportRadius(); }, kernel);
    ModelContext context = modelContext(properties, dx, h);
    FluidModels<D> models = selectFluidModels<D>(schemes, std::move(kernel), properties, context);
    context.artificialViscosity = std::holds_alternative<ArtificialViscosityMonaghan1992>(models.viscosity);
    context.laminarViscosity = std::holds_alternative<LaminarViscosityMorris1997>(models.viscosity);

    setup.patchNames = state.wallHeader.patchNames;
    setup.patchLayers = state.wallHeader.patchLayers;
    std::vector<Patch<D>> patches = selectPatches<D>(caseDirectory, boundaryDict, stateFile(start.path, "walls"), state.walls, setup.patchNames,
                                                     setup.patchLayers, context, support, share);
    selectIntegrator<D>(timeIntegration, schemes, models.shifting.enabled(), setup);

    for (int d = 0; d < D; ++d)
        if (state.periodic[static_cast<std::size_t>(d)] && state.domainMax[d] - state.domainMin[d] < 3.0 * support)
            throw FatalError(
                fmt::format("error: '{}': the periodic direction {} is {:g} long, shorter than three kernel support radii ({:g}); "
                            "lengthen the domain or reduce hdx",
                            stateFile(start.path, "fluid").string(), "xyz"[d], state.domainMax[d] - state.domainMin[d], 3.0 * support));
    setup.system = std::make_unique<FluidSystem<D>>(std::move(models), std::move(state.fluid), std::move(state.walls), std::move(patches),
                                                    state.domainMin, state.domainMax, properties.gravity, properties.gravityRampTime, state.periodic);
    setup.integrator->checkCompatible(*setup.system, timeIntegration.subDict("integrator"));
    setup.dictionaries.push_back(std::move(schemes));
    setup.dictionaries.push_back(std::move(timeIntegration));
    setup.dictionaries.push_back(std::move(fluidDict));
    setup.dictionaries.push_back(std::move(boundaryDict));
    return setup;
}

#ifdef SPHKIT_HAS_1D
template CaseSetup<1> setUpCase<1>(const std::filesystem::path&, const TimeDirectory&, const StateShare<1>*);
#endif
#ifdef SPHKIT_HAS_2D
template CaseSetup<2> setUpCase<2>(const std::filesystem::path&, const TimeDirectory&, const StateShare<2>*);
#endif
#ifdef SPHKIT_HAS_3D
template CaseSetup<3> setUpCase<3>(const std::filesystem::path&, const TimeDirectory&, const StateShare<3>*);
#endif

}  // namespace sph
