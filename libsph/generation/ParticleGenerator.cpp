#include "generation/ParticleGenerator.hpp"

#include "core/MemoryBudget.hpp"

#include "driver/CaseDirectory.hpp"
#include "driver/WallLayoutFromModel.hpp"
#include "generation/FluidRegions.hpp"
#include "generation/WallPatches.hpp"
#include "io/ParticleFile.hpp"
#include "neighbourSearch/CellLinkedList.hpp"
#include "physics/FluidProperties.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <cmath>
#include <functional>

namespace sph {

namespace {

template <int D>
bool insideDomain(const Vec<D>& x, const Vec<D>& lo, const Vec<D>& hi) {
    return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
}

// A warning when fluid particles [first, end) of a region lie beyond the box around every wall
// particle, in a direction that is not periodic: fluid put beside the tank rather than in it
// (not an error: walls may be obstacles in an open domain).
template <int D>
std::string outsideTheWalls(const std::string& region, const std::vector<Vec<D>>& fluid, std::size_t first, const std::vector<Vec<D>>& walls,
                            const std::vector<double>& periodic, double dx) {
    if (walls.empty()) return "";
    Vec<D> lo = walls.front(), hi = walls.front();
    for (const Vec<D>& w : walls) {
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
    }
    std::size_t outside = 0;
    for (std::size_t i = first; i < fluid.size(); ++i)
        for (int d = 0; d < D; ++d)
            if ((periodic.empty() || periodic[static_cast<std::size_t>(d)] == 0.0) &&
                (fluid[i][d] < lo[d] - 0.5 * dx || fluid[i][d] > hi[d] + 0.5 * dx)) {
                ++outside;
                break;
            }
    if (outside == 0) return "";
    return fmt::format(
        "fluid region '{}' has {} of its {} particles outside the box around the wall particles, from ({:g}) to ({:g}): "
        "is it outside the tank?",
        region, outside, fluid.size() - first, fmt::join(lo.data(), lo.data() + D, " "), fmt::join(hi.data(), hi.data() + D, " "));
}

// Two patches that lay most of their particles on each other: one patch listed twice under two
// names (patches that meet share a corner or an edge, a small part of either).
template <int D>
void requireDistinctPatches(const Dictionary& boundaries, const std::vector<std::string>& patchNames, const std::vector<int>& patchOf,
                            const std::vector<Vec<D>>& positions, const CellLinkedList<D>& cells, double dx) {
    std::vector<std::size_t> total(patchNames.size(), 0);
    std::vector<std::vector<std::size_t>> shared(patchNames.size(), std::vector<std::size_t>(patchNames.size(), 0));
    for (std::size_t k = 0; k < positions.size(); ++k) {
        const auto p = static_cast<std::size_t>(patchOf[k]);
        ++total[p];
        std::vector<bool> counted(patchNames.size(), false);
        cells.forEachNeighbour(positions[k], 1e-6 * dx, [&](std::uint32_t j, const Vec<D>&, double) {
            const auto q = static_cast<std::size_t>(patchOf[j]);
            if (q < p && !counted[q]) {
                counted[q] = true;
                ++shared[p][q];
            }
        });
    }
    for (std::size_t p = 0; p < patchNames.size(); ++p)
        for (std::size_t q = 0; q < p; ++q)
            if (2 * shared[p][q] > total[p])
                throw FatalError(boundaries.subDict(patchNames[p]).where(),
                                 fmt::format("wall patch '{}' lays {} of its {} particles on those of patch '{}' (the same patch listed twice?)",
                                             patchNames[p], shared[p][q], total[p], patchNames[q]));
}

template <int D>
GenerationSummary generate(const std::filesystem::path& caseDirectory, const Dictionary& dict, const std::filesystem::path& outputDirectory) {
    const double dx = dict.getPositive("spacing");
    const Dictionary& domain = dict.subDict("domain");
    const Vec<D> lo = domain.getVector<D>("min"), hi = domain.getVector<D>("max");
    for (int d = 0; d < D; ++d)
        if (!(hi[d] > lo[d])) domain.fail("max", fmt::format("must exceed min in every direction (direction {}: {:g} <= {:g})", d, hi[d], lo[d]));
    // Before anything is allocated: the domain's lattice is walked by the shape fillers and
    // covered by the generator's neighbour search (16 bytes a lattice point).
    double latticePoints = 1.0;
    for (int d = 0; d < D; ++d) {
        const double across = (hi[d] - lo[d]) / dx;
        if (!(across <= maxSpacingsAcross))
            dict.fail("spacing", fmt::format("the domain is {:.3g} spacings of {:g} across in direction {} (at most {}): is the spacing a slip?",
                                             across, dx, d, maxSpacingsAcross));
        latticePoints *= across + 1.0;
    }
    requireMemory(16.0 * latticePoints,
                  fmt::format("{}: spacing {:g} over the domain ({:.3g} lattice points)", dict.where().str(), dx, latticePoints));
    std::vector<double> periodic;
    if (domain.found("periodic")) {
        periodic.assign(static_cast<std::size_t>(D), 0.0);
        for (const std::string& axis : domain.get<std::vector<std::string>>("periodic")) {
            const auto at = std::string("xyz").substr(0, D).find(axis);
            if (axis.size() != 1 || at == std::string::npos)
                domain.fail("periodic",
                            fmt::format("unknown direction '{}'; valid directions are: {}", axis, std::string("x y z").substr(0, 2 * D - 1)));
            periodic[at] = 1.0;
        }
    }
    const std::string initialPressure = dict.getOrDefault<std::string>("initialPressure", "none");
    if (initialPressure != "none" && initialPressure != "hydrostatic" && initialPressure != "analytic")
        dict.fail("initialPressure", "expected none, hydrostatic or analytic, found '" + initialPressure + "'");

    const Dictionary fluidPropertiesDict = readCaseDictionary(caseDirectory, "constant/fluidProperties");
    const FluidProperties<D> properties = readFluidProperties<D>(fluidPropertiesDict);
    const double rho0 = properties.rho0;
    const double volume = std::pow(dx, D);
    const GenerationDomain<D> shapeDomain{lo, hi, caseDirectory};

    // Walls first: fluid particles overlapping them are dropped.
    ParticleSet<D> walls("walls");
    std::vector<std::string> patchNames, notes;
    const Dictionary* boundaries = dict.findSubDict("boundaries");
    WallPatchParticles<D> allWalls;
    WallLayoutFromModel<D> layoutFromModel(caseDirectory, dx, properties);
    std::vector<int> patchOf;
    std::vector<std::function<bool(const Vec<D>&)>> solids;
    if (boundaries) {
        for (const std::string& name : boundaries->keywords()) {
            const Dictionary& patch = boundaries->subDict(name);
            const WallLayout layout = wallLayout(patch, [&] {
                std::string why;
                const WallLayout fromModel = layoutFromModel(name, patch, why);
                notes.push_back(fmt::format("wall patch '{}': {}", name, why));
                return fromModel;
            });
            const WallPatchParticles<D> generated = generateWallPatch<D>(patch, dx, layout, shapeDomain);
            for (const std::string& note : generated.notes) notes.push_back(fmt::format("wall patch '{}': {}", name, note));
            for (std::size_t k = 0; k < generated.positions.size(); ++k) {
                if (!insideDomain<D>(generated.positions[k], lo, hi))
                    throw FatalError(patch.where(), fmt::format("wall patch '{}' has a particle at ({:g}) outside the domain [({:g}), ({:g})]", name,
                                                                fmt::join(generated.positions[k], " "), fmt::join(lo, " "), fmt::join(hi, " ")));
                allWalls.add(generated.positions[k], generated.normals[k], generated.spacings[k], generated.layers[k], generated.areas[k]);
                patchOf.push_back(static_cast<int>(patchNames.size()));
            }
            patchNames.push_back(name);
            if (generated.solid) solids.push_back(generated.solid);
        }
    }
    CellLinkedList<D> wallCells(lo, hi, dx);
    wallCells.build(allWalls.positions);
    if (boundaries) requireDistinctPatches(*boundaries, patchNames, patchOf, allWalls.positions, wallCells, dx);

    // A fluid lattice point less than dx/2 from a wall particle overlaps the wall. Where every
    // such particle belongs to a one-layer wall (its particles on the wall's surface) the point
    // is moved out along their normals to dx/2 in front of them rather than dropped: on a curved
    // wall dropping would remove a ring of fluid dx/2 thick and lower the water by it. Behind
    // such a wall, or near a layered wall, it is dropped.
    std::vector<bool> oneLayerPatch(patchNames.size(), true);
    for (std::size_t j = 0; j < allWalls.layers.size(); ++j)
        if (allWalls.layers[j] > 0) oneLayerPatch[static_cast<std::size_t>(patchOf[j])] = false;
    const double clearance = 0.5 * dx * (1.0 - 1e-9);
    const auto clearOfTheWalls = [&](Vec<D> x) -> std::optional<Vec<D>> {
        for (int pass = 0; pass < D; ++pass) {  // a corner pushes along each of its walls in turn
            bool drop = false;
            double deepest = 0.0;
            Vec<D> push = Vec<D>::Zero();
            wallCells.forEachNeighbour(x, clearance, [&](std::uint32_t j, const Vec<D>& fromWall, double) {
                const double gap = fromWall.dot(allWalls.normals[j]);
                if (!oneLayerPatch[static_cast<std::size_t>(patchOf[j])] || gap <= 0.0)
                    drop = true;
                else if (0.5 * dx - gap > deepest) {
                    deepest = 0.5 * dx - gap;
                    push = deepest * allWalls.normals[j];
                }
            });
            if (drop) return std::nullopt;
            if (deepest == 0.0) return x;
            x += push;
        }
        bool overlaps = false;
        wallCells.forEachNeighbour(x, clearance, [&](std::uint32_t, const Vec<D>&, double) { overlaps = true; });
        return overlaps ? std::nullopt : std::optional<Vec<D>>(x);
    };

    // Fluid regions.
    std::vector<Vec<D>> fluidPositions, fluidVelocities;
    std::vector<double> surfaceHeight;     // per particle: the top of its region along -g
    std::vector<double> initialPressures;  // per particle, with initialPressure analytic
    const Vec<D> up = properties.gravity.norm() > 0.0 ? Vec<D>(-properties.gravity.normalized()) : Vec<D>::Zero();
    std::size_t dropped = 0;
    std::vector<std::string> warnings;
    const Dictionary& fluid = dict.subDict("fluid");
    for (const std::string& name : fluid.keywords()) {
        const Dictionary& region = fluid.subDict(name);
        const FluidRegionParticles<D> filled = fillFluidRegion<D>(region, dx, shapeDomain);
        for (const std::string& note : filled.notes) notes.push_back(fmt::format("fluid region '{}': {}", name, note));
        double top = -std::numeric_limits<double>::infinity();
        std::size_t first = fluidPositions.size();
        for (const Vec<D>& latticePoint : filled.positions) {
            if (!insideDomain<D>(latticePoint, lo, hi))
                throw FatalError(region.where(), fmt::format("fluid region '{}' has a particle at ({:g}) outside the domain [({:g}), ({:g})]", name,
                                                             fmt::join(latticePoint, " "), fmt::join(lo, " "), fmt::join(hi, " ")));
            if (std::any_of(solids.begin(), solids.end(), [&](const auto& solid) { return solid(latticePoint); })) {
                ++dropped;
                continue;
            }
            const std::optional<Vec<D>> kept = clearOfTheWalls(latticePoint);
            if (!kept) {
                ++dropped;
                continue;
            }
            const Vec<D> x = *kept;
            fluidPositions.push_back(x);
            fluidVelocities.push_back(filled.initialField ? filled.initialField->velocity(x, 0.0) : filled.velocity);
            if (initialPressure == "analytic") {
                if (!filled.initialField || !filled.initialField->hasPressure())
                    dict.fail("initialPressure",
                              fmt::format("'analytic' needs fluid region '{}' to take its velocity from a solution with a pressure "
                                          "field (velocity {{ type taylorGreen; ... }}, say)",
                                          name));
                initialPressures.push_back(filled.initialField->pressure(x, 0.0, {rho0, properties.gravity}));
            }
            top = std::max(top, x.dot(up) + 0.5 * dx);
        }
        surfaceHeight.resize(fluidPositions.size(), top);
        if (fluidPositions.size() == first) throw FatalError(region.where(), fmt::format("fluid region '{}' holds no particle", name));
        if (const std::string outside = outsideTheWalls(name, fluidPositions, first, allWalls.positions, periodic, dx); !outside.empty())
            warnings.push_back(outside);
    }

    const auto densityFor = [&](double p) { return std::visit([&](const auto& eos) { return eos.density(eos.p0 + p); }, properties.eos); };
    const auto hydrostaticPressure = [&](const Vec<D>& x, double top) { return rho0 * properties.gravity.norm() * (top - x.dot(up)); };
    const auto fluidDensity = [&](std::size_t i) {
        if (initialPressure == "analytic") return densityFor(initialPressures[i]);
        if (initialPressure == "hydrostatic") return densityFor(hydrostaticPressure(fluidPositions[i], surfaceHeight[i]));
        return rho0;
    };

    ParticleSet<D> fluidSet("fluid");
    fluidSet.resize(fluidPositions.size());
    auto& velocity = fluidSet.addVector("velocity", Vec<D>::Zero());
    auto& density = fluidSet.addScalar("density", rho0);
    // The pressure the solver will take from the density, so that the initial state can be coloured by it.
    const auto pressureOf = [&](double rho) { return std::visit([&](const auto& eos) { return eos.pressure(rho); }, properties.eos); };
    auto& pressure = fluidSet.addScalar("pressure", 0.0);
    fluidSet.addScalar("mass", rho0 * volume);
    for (std::size_t i = 0; i < fluidPositions.size(); ++i) {
        fluidSet.position[i] = fluidPositions[i];
        fluidSet.globalId[i] = static_cast<std::int64_t>(i);
        velocity[i] = fluidVelocities[i];
        density[i] = fluidDensity(i);
        pressure[i] = pressureOf(density[i]);
    }

    walls.resize(allWalls.positions.size());
    auto& normal = walls.addVector("normal", Vec<D>::Zero());
    auto& spacing = walls.addScalar("spacing", dx);
    auto& area = walls.addScalar("area", 0.0);
    auto& wallDensity = walls.addScalar("density", rho0);
    auto& wallPressure = walls.addScalar("pressure", 0.0);
    walls.addScalar("mass", rho0 * volume);
    auto& patch = walls.addInteger("patch", 0);
    auto& layer = walls.addInteger("layer", 0);
    const double highestSurface = surfaceHeight.empty() ? 0.0 : *std::max_element(surfaceHeight.begin(), surfaceHeight.end());
    for (std::size_t k = 0; k < allWalls.positions.size(); ++k) {
        walls.position[k] = allWalls.positions[k];
        walls.globalId[k] = static_cast<std::int64_t>(k);
        normal[k] = allWalls.normals[k];
        spacing[k] = allWalls.spacings[k];
        area[k] = allWalls.areas[k];
        patch[k] = patchOf[k];
        layer[k] = allWalls.layers[k];
        wallDensity[k] =
            initialPressure == "hydrostatic" ? std::max(rho0, densityFor(hydrostaticPressure(allWalls.positions[k], highestSurface))) : rho0;
        wallPressure[k] = pressureOf(wallDensity[k]);
    }

    StateHeader header;
    header.dimension = D;
    header.spacing = dx;
    header.domainMin.assign(lo.data(), lo.data() + D);
    header.domainMax.assign(hi.data(), hi.data() + D);
    header.periodic = periodic;
    dict.checkUnused();
    std::filesystem::create_directories(outputDirectory);
    // Walls first: the solver takes a time directory with a fluid.vtu for a complete state.
    StateHeader wallHeader = header;
    wallHeader.patchNames = patchNames;
    writeParticleFile(outputDirectory / "walls.vtu", walls, wallHeader);
    writeParticleFile(outputDirectory / "fluid.vtu", fluidSet, header);
    return {D, fluidSet.size(), walls.size(), dropped, warnings, notes};
}

}  // namespace

GenerationSummary generateParticles(const std::filesystem::path& caseDirectory, bool overwrite) {
    const Dictionary dict = readCaseDictionary(caseDirectory, "system/generateParticlesDict");
    const std::filesystem::path output = caseDirectory / "0";
    if (!overwrite && std::filesystem::exists(output / "fluid.vtu"))
        throw FatalError("error: '" + (output / "fluid.vtu").string() + "' exists; remove it (./Allclean) or pass -overwrite");
    const int dimension = dict.get<int>("dimension");
    GenerationSummary summary;
    switch (dimension) {
        case 1: summary = generate<1>(caseDirectory, dict, output); break;
        case 2: summary = generate<2>(caseDirectory, dict, output); break;
        case 3: summary = generate<3>(caseDirectory, dict, output); break;
        default: dict.fail("dimension", fmt::format("must be 1, 2 or 3, found {}", dimension));
    }
    // The later times of the state just replaced: the solver would resume from them.
    if (overwrite) removeTimeDirectories(timesAfter(caseDirectory, 0.0));
    return summary;
}

}  // namespace sph
