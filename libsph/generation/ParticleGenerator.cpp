#include "generation/ParticleGenerator.hpp"

#include "core/MemoryBudget.hpp"

#include "driver/CaseDirectory.hpp"
#include "driver/WallLayoutFromModel.hpp"
#include "generation/FluidRegions.hpp"
#include "generation/WallPatches.hpp"
#include "io/ParticleFile.hpp"
#include "io/ParticleState.hpp"
#include "neighbourSearch/SparseCellList.hpp"
#include "neighbourSearch/WallSide.hpp"
#include "physics/FluidProperties.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <optional>
#include <regex>

namespace sph {

namespace {

template <int D>
bool insideDomain(const Vec<D>& x, const Vec<D>& lo, const Vec<D>& hi) {
    return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
}

// Each entry summed over the generators of a share (as it is without one).
std::vector<double> sumOverShares(const GenerationShare* share, const std::vector<double>& values) {
    if (!share) return values;
    const std::vector<double> all = share->gatherToAll(values);
    std::vector<double> sums(values.size(), 0.0);
    for (std::size_t k = 0; k < all.size(); ++k) sums[k % values.size()] += all[k];
    return sums;
}

double largestOverShares(const GenerationShare* share, double value) {
    if (!share) return value;
    const std::vector<double> all = share->gatherToAll(std::span(&value, 1));
    return *std::max_element(all.begin(), all.end());
}

// The box around every wall particle, and how many fluid particles [first, end) of a region lie
// beyond it in a direction that is not periodic.
template <int D>
struct WallBox {
    Vec<D> lo, hi;
    bool empty;

    explicit WallBox(const std::vector<Vec<D>>& walls) : lo(Vec<D>::Zero()), hi(Vec<D>::Zero()), empty(walls.empty()) {
        if (empty) return;
        lo = hi = walls.front();
        for (const Vec<D>& w : walls) {
            lo = lo.cwiseMin(w);
            hi = hi.cwiseMax(w);
        }
    }

    std::size_t countOutside(const std::vector<Vec<D>>& fluid, std::size_t first, const std::vector<double>& periodic, double dx) const {
        std::size_t outside = 0;
        for (std::size_t i = first; !empty && i < fluid.size(); ++i)
            for (int d = 0; d < D; ++d)
                if ((periodic.empty() || periodic[static_cast<std::size_t>(d)] == 0.0) &&
                    (fluid[i][d] < lo[d] - 0.5 * dx || fluid[i][d] > hi[d] + 0.5 * dx)) {
                    ++outside;
                    break;
                }
        return outside;
    }

    // A warning for fluid put beside the tank rather than in it (not an error: walls may be
    // obstacles in an open domain).
    std::string warning(const std::string& region, std::size_t outside, std::size_t particles) const {
        return fmt::format(
            "fluid region '{}' has {} of its {} particles outside the box around the wall particles, from ({:g}) to ({:g}): "
            "is it outside the tank?",
            region, outside, particles, fmt::join(lo.data(), lo.data() + D, " "), fmt::join(hi.data(), hi.data() + D, " "));
    }
};

// Two patches that lay most of their particles on each other: one patch listed twice under two
// names (patches that meet share a corner or an edge, a small part of either).
template <int D>
void requireDistinctPatches(const Dictionary& boundaries, const std::vector<std::string>& patchNames, const std::vector<int>& patchOf,
                            const std::vector<Vec<D>>& positions, const SparseCellList<D>& cells, double dx) {
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

// The domain and its lattice spacing, checked before anything is allocated.
template <int D>
struct LatticeDomain {
    double dx;
    Vec<D> lo, hi;
    std::vector<double> periodic;  // empty, or 1 per periodic direction
};

template <int D>
LatticeDomain<D> readLatticeDomain(const Dictionary& dict) {
    LatticeDomain<D> lattice;
    lattice.dx = dict.getPositive("spacing");
    const Dictionary& domain = dict.subDict("domain");
    lattice.lo = domain.getVector<D>("min");
    lattice.hi = domain.getVector<D>("max");
    const Vec<D>&lo = lattice.lo, &hi = lattice.hi;
    for (int d = 0; d < D; ++d)
        if (!(hi[d] > lo[d])) domain.fail("max", fmt::format("must exceed min in every direction (direction {}: {:g} <= {:g})", d, hi[d], lo[d]));
    // The domain's lattice is walked by the shape fillers, and a fluid region may fill it: at
    // least a position and a velocity (16 bytes in 1D) a lattice point.
    double latticePoints = 1.0;
    for (int d = 0; d < D; ++d) {
        const double across = (hi[d] - lo[d]) / lattice.dx;
        if (!(across <= maxSpacingsAcross))
            dict.fail("spacing", fmt::format("the domain is {:.3g} spacings of {:g} across in direction {} (at most {}): is the spacing a slip?",
                                             across, lattice.dx, d, maxSpacingsAcross));
        latticePoints *= across + 1.0;
    }
    requireMemory(16.0 * latticePoints,
                  fmt::format("{}: spacing {:g} over the domain ({:.3g} lattice points)", dict.where().str(), lattice.dx, latticePoints));
    if (domain.found("periodic")) {
        lattice.periodic.assign(static_cast<std::size_t>(D), 0.0);
        for (const std::string& axis : domain.get<std::vector<std::string>>("periodic")) {
            const auto at = std::string("xyz").substr(0, D).find(axis);
            if (axis.size() != 1 || at == std::string::npos)
                domain.fail("periodic",
                            fmt::format("unknown direction '{}'; valid directions are: {}", axis, std::string("x y z").substr(0, 2 * D - 1)));
            lattice.periodic[at] = 1.0;
        }
    }
    return lattice;
}

// Every wall patch's particles, in the order the patches are listed.
template <int D>
struct GeneratedWalls {
    WallPatchParticles<D> particles;
    std::vector<std::string> patchNames;
    std::vector<double> patchLayers;                         // the layers the fluid finds behind each patch's faces
    std::vector<int> patchOf;                                // per particle
    std::vector<bool> patchIsSolid;                          // a body with the fluid outside
    std::vector<std::function<bool(const Vec<D>&)>> solids;  // where no fluid goes
};

template <int D>
GeneratedWalls<D> generateWalls(const Dictionary* boundaries, const LatticeDomain<D>& lattice, WallLayoutFromModel<D>& layoutFromModel,
                                const GenerationDomain<D>& shapeDomain, std::vector<std::string>& notes) {
    GeneratedWalls<D> walls;
    if (!boundaries) return walls;
    for (const std::string& name : boundaries->keywords()) {
        const Dictionary& patch = boundaries->subDict(name);
        const auto noted = [&](const std::string& why) {
            if (!why.empty()) notes.push_back(fmt::format("wall patch '{}': {}", name, why));
        };
        const WallLayout layout = wallLayout(
            patch,
            [&] {
                std::string why;
                const WallLayout fromModel = layoutFromModel(name, patch, why);
                noted(why);
                return fromModel;
            },
            [&] {
                std::string why;
                const std::optional<double> offset = layoutFromModel.offsetOf(name, why);
                noted(why);
                return offset;
            });
        const WallPatchParticles<D> generated = generateWallPatch<D>(patch, lattice.dx, layout, shapeDomain);
        for (const std::string& note : generated.notes) notes.push_back(fmt::format("wall patch '{}': {}", name, note));
        for (std::size_t k = 0; k < generated.positions.size(); ++k) {
            if (!insideDomain<D>(generated.positions[k], lattice.lo, lattice.hi))
                throw FatalError(patch.where(),
                                 fmt::format("wall patch '{}' has a particle at ({:g}) outside the domain [({:g}), ({:g})]", name,
                                             fmt::join(generated.positions[k], " "), fmt::join(lattice.lo, " "), fmt::join(lattice.hi, " ")));
            walls.particles.add(generated.positions[k], generated.normals[k], generated.spacings[k], generated.layers[k], generated.areas[k]);
            walls.patchOf.push_back(static_cast<int>(walls.patchNames.size()));
        }
        walls.patchNames.push_back(name);
        const int deepest = generated.layers.empty() ? -1 : *std::max_element(generated.layers.begin(), generated.layers.end());
        walls.patchLayers.push_back(generated.filledThrough ? layout.layers : deepest + 1);
        walls.patchIsSolid.push_back(static_cast<bool>(generated.solid));
        if (generated.solid) walls.solids.push_back(generated.solid);
    }
    return walls;
}

// A fluid lattice point less than dx/2 from a wall particle overlaps the wall, and so does one
// less than dx/2 in front of a one-layer wall's element (its particle on the wall's surface,
// the point within half the particle's spacing of it along the wall): on a curved or slanted
// wall a lattice point between two wall particles can be further than dx/2 from both and 0.13
// dx from the surface (cylinderArray2D), where the wall's force then holds it from the first
// step. Where every such particle belongs to a one-layer wall the point is moved out along their
// normals to dx/2 in front of them rather than dropped: on a curved wall dropping would remove a
// ring of fluid dx/2 thick and lower the water by it. Behind such a wall, or near a layered
// wall, it is dropped.
template <int D>
class WallClearance {
public:
    WallClearance(const GeneratedWalls<D>& walls, const SparseCellList<D>& wallCells, double dx)
        : walls_(walls), wallCells_(wallCells), dx_(dx), clearance_(0.5 * dx * (1.0 - 1e-9)), oneLayerPatch_(walls.patchNames.size(), true) {
        for (std::size_t j = 0; j < walls.particles.layers.size(); ++j) {
            if (walls.particles.layers[j] > 0) oneLayerPatch_[static_cast<std::size_t>(walls.patchOf[j])] = false;
            reach_ = std::max(reach_, std::hypot(clearance_, halfElement(j)));
        }
    }

    // Where the point at x goes: moved clear of the walls, or nowhere (dropped).
    std::optional<Vec<D>> operator()(Vec<D> x) const {
        for (int pass = 0; pass < D; ++pass) {  // a corner pushes along each of its walls in turn
            bool drop = false;
            double deepest = 0.0;
            Vec<D> push = Vec<D>::Zero();
            wallCells_.forEachNeighbour(x, reach_, [&](std::uint32_t j, const Vec<D>& fromWall, double r2) {
                const double gap = fromWall.dot(walls_.particles.normals[j]);
                const bool oneLayer = oneLayerPatch_[static_cast<std::size_t>(walls_.patchOf[j])];
                const bool overlaps =
                    r2 < clearance_ * clearance_ || (oneLayer && gap < clearance_ && r2 - gap * gap <= halfElement(j) * halfElement(j));
                if (!overlaps) return;
                if (!oneLayer || gap <= 0.0)
                    drop = true;
                else if (0.5 * dx_ - gap > deepest) {
                    deepest = 0.5 * dx_ - gap;
                    push = deepest * walls_.particles.normals[j];
                }
            });
            if (drop) return std::nullopt;
            if (deepest == 0.0) return x;
            x += push;
        }
        bool overlaps = false;
        wallCells_.forEachNeighbour(x, clearance_, [&](std::uint32_t, const Vec<D>&, double) { overlaps = true; });
        return overlaps ? std::nullopt : std::optional<Vec<D>>(x);
    }

private:
    // How far along the wall wall particle j's element reaches from it: half its spacing in 2D,
    // half the diagonal of its square in 3D.
    double halfElement(std::size_t j) const { return 0.5 * walls_.particles.spacings[j] * std::sqrt(D - 1.0) * (1.0 + 1e-9); }

    const GeneratedWalls<D>& walls_;
    const SparseCellList<D>& wallCells_;
    double dx_, clearance_;
    double reach_ = 0.0;  // the furthest a wall particle can be from a point that overlaps its element
    std::vector<bool> oneLayerPatch_;
};

// The fluid regions' particles, in the order the regions are listed.
template <int D>
struct GeneratedFluid {
    std::vector<Vec<D>> positions, velocities;
    std::vector<double> surfaceHeight;     // per particle: the top of its region along -g
    std::vector<double> initialPressures;  // per particle, with initialPressure analytic
    std::vector<double> regionSizes;       // per region: its particles (of this share)
    std::vector<double> regionTops;        // per region: its top along -g (of every share)
    std::size_t dropped = 0;
    std::vector<std::string> warnings;
};

// The unit vector against gravity (zero without gravity): fluid tops and depths are measured along it.
template <int D>
Vec<D> upwards(const FluidProperties<D>& properties) {
    return properties.gravity.norm() > 0.0 ? Vec<D>(-properties.gravity.normalized()) : Vec<D>::Zero();
}

template <int D>
GeneratedFluid<D> fillFluid(const Dictionary& dict, const LatticeDomain<D>& lattice, const GeneratedWalls<D>& walls,
                            const WallClearance<D>& clearOfTheWalls, const GenerationDomain<D>& shapeDomain, const std::string& initialPressure,
                            const FluidProperties<D>& properties, const GenerationShare* share, std::vector<std::string>& notes) {
    GeneratedFluid<D> out;
    const Vec<D> up = upwards(properties);
    const Dictionary& fluid = dict.subDict("fluid");
    const WallBox<D> wallBox(walls.particles.positions);
    for (const std::string& name : fluid.keywords()) {
        const Dictionary& region = fluid.subDict(name);
        double top = -std::numeric_limits<double>::infinity();
        const std::size_t first = out.positions.size();
        const auto fillRegion = [&] {
            const FluidRegionParticles<D> filled = fillFluidRegion<D>(region, lattice.dx, shapeDomain);
            for (const std::string& note : filled.notes) notes.push_back(fmt::format("fluid region '{}': {}", name, note));
            for (const Vec<D>& latticePoint : filled.positions) {
                if (!insideDomain<D>(latticePoint, lattice.lo, lattice.hi))
                    throw FatalError(region.where(),
                                     fmt::format("fluid region '{}' has a particle at ({:g}) outside the domain [({:g}), ({:g})]", name,
                                                 fmt::join(latticePoint, " "), fmt::join(lattice.lo, " "), fmt::join(lattice.hi, " ")));
                const bool inSolid = std::any_of(walls.solids.begin(), walls.solids.end(), [&](const auto& solid) { return solid(latticePoint); });
                const std::optional<Vec<D>> kept = inSolid ? std::nullopt : clearOfTheWalls(latticePoint);
                if (!kept) {
                    ++out.dropped;
                    continue;
                }
                const Vec<D> x = *kept;
                out.positions.push_back(x);
                out.velocities.push_back(filled.initialField ? filled.initialField->velocity(x, 0.0) : filled.velocity);
                if (initialPressure == "analytic") {
                    if (!filled.initialField || !filled.initialField->hasPressure())
                        dict.fail("initialPressure",
                                  fmt::format("'analytic' needs fluid region '{}' to take its velocity from a solution with a pressure "
                                              "field (velocity {{ type taylorGreen; ... }}, say)",
                                              name));
                    out.initialPressures.push_back(filled.initialField->pressure(x, 0.0, {properties.rho0, properties.gravity}));
                }
                top = std::max(top, x.dot(up) + 0.5 * lattice.dx);
            }
        };
        share ? share->together(fillRegion) : fillRegion();
        out.regionTops.push_back(largestOverShares(share, top));
        out.surfaceHeight.resize(out.positions.size(), out.regionTops.back());
        out.regionSizes.push_back(static_cast<double>(out.positions.size() - first));
        const auto outsideOf = static_cast<double>(wallBox.countOutside(out.positions, first, lattice.periodic, lattice.dx));
        const std::vector<double> counts = sumOverShares(share, {out.regionSizes.back(), outsideOf});
        if (counts[0] == 0.0) throw FatalError(region.where(), fmt::format("fluid region '{}' holds no particle", name));
        if (counts[1] > 0.0) out.warnings.push_back(wallBox.warning(name, static_cast<std::size_t>(counts[1]), static_cast<std::size_t>(counts[0])));
    }
    return out;
}

// The initial state's density and pressure: uniform, hydrostatic below each region's top, or
// from the analytic solution's pressure.
template <int D>
struct InitialState {
    const FluidProperties<D>& properties;
    std::string initialPressure;

    double density(double p) const {
        return std::visit([&](const auto& eos) { return eos.density(eos.p0 + p); }, properties.eos);
    }
    // The pressure the solver will take from the density, so that the initial state can be coloured by it.
    double pressure(double rho) const {
        return std::visit([&](const auto& eos) { return eos.pressure(rho); }, properties.eos);
    }
    double hydrostaticPressure(const Vec<D>& x, double top) const {
        return properties.rho0 * properties.gravity.norm() * (top - x.dot(upwards(properties)));
    }
};

template <int D>
ParticleSet<D> fluidParticleSet(const GeneratedFluid<D>& generated, const InitialState<D>& state, double dx) {
    const double rho0 = state.properties.rho0;
    ParticleSet<D> fluidSet("fluid");
    fluidSet.resize(generated.positions.size());
    auto& velocity = fluidSet.add(fields::velocity, Vec<D>::Zero());
    auto& density = fluidSet.add(fields::density, rho0);
    auto& pressure = fluidSet.add(fields::pressure, 0.0);
    fluidSet.add(fields::mass, rho0 * std::pow(dx, D));
    for (std::size_t i = 0; i < generated.positions.size(); ++i) {
        fluidSet.position[i] = generated.positions[i];
        fluidSet.globalId[i] = static_cast<std::int64_t>(i);
        velocity[i] = generated.velocities[i];
        if (state.initialPressure == "analytic")
            density[i] = state.density(generated.initialPressures[i]);
        else if (state.initialPressure == "hydrostatic")
            density[i] = state.density(state.hydrostaticPressure(generated.positions[i], generated.surfaceHeight[i]));
        else
            density[i] = rho0;
        pressure[i] = state.pressure(density[i]);
    }
    return fluidSet;
}

// Wall particles start at the hydrostatic pressure below the highest fluid surface (at least rho0).
template <int D>
ParticleSet<D> wallParticleSet(const GeneratedWalls<D>& generated, const InitialState<D>& state, double highestSurface, double dx) {
    const double rho0 = state.properties.rho0;
    const WallPatchParticles<D>& all = generated.particles;
    ParticleSet<D> walls("walls");
    walls.resize(all.positions.size());
    auto& normal = walls.add(fields::normal, Vec<D>::Zero());
    auto& spacing = walls.add(fields::spacing, dx);
    auto& area = walls.add(fields::area, 0.0);
    auto& wallDensity = walls.add(fields::density, rho0);
    auto& wallPressure = walls.add(fields::pressure, 0.0);
    walls.add(fields::mass, rho0 * std::pow(dx, D));
    auto& patch = walls.add(fields::patch, 0);
    auto& layer = walls.add(fields::layer, 0);
    for (std::size_t k = 0; k < all.positions.size(); ++k) {
        walls.position[k] = all.positions[k];
        walls.globalId[k] = static_cast<std::int64_t>(k);
        normal[k] = all.normals[k];
        spacing[k] = all.spacings[k];
        area[k] = all.areas[k];
        patch[k] = generated.patchOf[k];
        layer[k] = all.layers[k];
        wallDensity[k] = state.initialPressure == "hydrostatic"
                             ? std::max(rho0, state.density(state.hydrostaticPressure(all.positions[k], highestSurface)))
                             : rho0;
        wallPressure[k] = state.pressure(wallDensity[k]);
    }
    return walls;
}

// The fluid particles' ids: their places in the serial generator's order, region by region,
// each region's lattice rows in order, so that the shares' particles of a region follow each
// other in rank order.
std::vector<std::int64_t> serialIds(const GenerationShare* share, const std::vector<double>& regionSizes) {
    const std::size_t regions = regionSizes.size();
    const std::vector<double> all = share ? share->gatherToAll(regionSizes) : regionSizes;
    const auto rank = static_cast<std::size_t>(share ? share->rows.rank : 0);
    std::vector<std::int64_t> ids;
    double regionsBefore = 0.0;
    for (std::size_t k = 0; k < regions; ++k) {
        double before = regionsBefore;
        for (std::size_t r = 0; r < rank; ++r) before += all[r * regions + k];
        for (std::size_t j = 0; j < static_cast<std::size_t>(regionSizes[k]); ++j)
            ids.push_back(static_cast<std::int64_t>(before) + static_cast<std::int64_t>(j));
        for (std::size_t r = 0; r < all.size() / regions; ++r) regionsBefore += all[r * regions + k];
    }
    return ids;
}

// The particles' places in the serial order, for a share's pieces: their ids.
template <int D>
void addSerialPlaces(ParticleSet<D>& set) {
    set.add(fields::orderCell, 0);
    auto& place = set.add(fields::orderRank, 0);
    for (std::size_t i = 0; i < set.size(); ++i) place[i] = static_cast<int>(set.globalId[i]);
}

// A wall patch whose normals point away from the fluid beside it (a polyline's `side` the wrong
// way round, a circle's `fluidInside` wrong), or with fluid on both sides (a polyline drawn
// through a fluid region as a baffle: a polyline has one side): the solver would run it with
// fluid behind the wall (a 2D baffle polyline on the correction ran with 57 fluid particles
// behind it from the first step). Each fluid particle next to a wall counts for its nearest
// wall particle's patch, behind it as wallPenetrations judges (fluid beside a convex corner,
// behind the corner particle's plane but in front of a face's, is in front); a patch with
// more than a quarter of them behind it stops the generator, as facing away with more than three
// quarters (about half lie behind a one-sided baffle).
template <int D>
void requireWallsFacingTheirFluid(const Dictionary& boundaries, const GeneratedWalls<D>& walls, const LatticeDomain<D>& lattice,
                                  const std::vector<Vec<D>>& fluid, const GenerationShare* share) {
    // Within 1.5 dx: fluid lattice points on a layered wall's own lattice are dropped, which
    // leaves the nearest fluid a whole dx from the wall particles.
    const double reach = 1.5 * lattice.dx;
    SparseCellList<D> wallCells(lattice.lo, lattice.hi, reach);
    wallCells.build(walls.particles.positions);
    const std::size_t patches = walls.patchNames.size();
    std::vector<double> counts(2 * patches, 0.0);  // per patch: fluid next to it, and of those behind it
    for (const Vec<D>& x : fluid) {
        const auto side = wallSide<D>(walls.particles.normals.data(), walls.particles.spacings.data(), walls.particles.layers.data(),
                                      [&](auto&& visit) { wallCells.forEachNeighbour(x, reach, visit); });
        if (!side) continue;
        const auto p = static_cast<std::size_t>(walls.patchOf[side->nearestWall]);
        counts[2 * p] += 1.0;
        if (side->behind) counts[2 * p + 1] += 1.0;
    }
    const std::vector<double> totals = sumOverShares(share, counts);
    for (std::size_t p = 0; p < patches; ++p) {
        const double next = totals[2 * p], behind = totals[2 * p + 1];
        if (4.0 * behind > 3.0 * next)
            throw FatalError(boundaries.subDict(walls.patchNames[p]).where(),
                             fmt::format("wall patch '{}' faces away from its fluid: {} of the {} fluid particles next to it lie behind its "
                                         "wall particles' normals (a polyline's or polygon's `side` left for right, a circle's, ellipse's or "
                                         "surface's `fluidInside` the wrong way?)",
                                         walls.patchNames[p], behind, next));
        if (4.0 * behind > next)
            throw FatalError(boundaries.subDict(walls.patchNames[p]).where(),
                             fmt::format("wall patch '{}' has fluid on both sides: {} of the {} fluid particles next to it lie behind its wall "
                                         "particles' normals ({})",
                                         walls.patchNames[p], behind, next,
                                         walls.patchIsSolid[p] ? "a solid body this small is below what the spacing resolves: its wall particles "
                                                                 "do not outline it; make it a few spacings across, or the spacing finer"
                                                               : "a polyline or polygon has one side; a wall with fluid on both is a solid "
                                                                 "body, a closed polygon with the fluid outside, or two patches back to back"));
    }
}

template <int D>
GenerationSummary generate(const std::filesystem::path& caseDirectory, const Dictionary& dict, const std::filesystem::path& outputDirectory,
                           const GenerationShare* share) {
    const LatticeDomain<D> lattice = readLatticeDomain<D>(dict);
    const double dx = lattice.dx;
    const std::string initialPressure = dict.getOrDefault<std::string>("initialPressure", "none");
    if (initialPressure != "none" && initialPressure != "hydrostatic" && initialPressure != "analytic")
        dict.fail("initialPressure", "expected none, hydrostatic or analytic, found '" + initialPressure + "'");
    const Dictionary fluidPropertiesDict = readCaseDictionary(caseDirectory, "constant/fluidProperties");
    const FluidProperties<D> properties = readFluidProperties<D>(fluidPropertiesDict);
    const GenerationDomain<D> shapeDomain{lattice.lo, lattice.hi, caseDirectory, share ? share->rows : LatticeShare{}};

    // Walls first: fluid particles overlapping them are dropped.
    std::vector<std::string> notes;
    const Dictionary* boundaries = dict.findSubDict("boundaries");
    WallLayoutFromModel<D> layoutFromModel(caseDirectory, dx, properties);
    const GeneratedWalls<D> walls = generateWalls(boundaries, lattice, layoutFromModel, shapeDomain, notes);
    SparseCellList<D> wallCells(lattice.lo, lattice.hi, dx);
    wallCells.build(walls.particles.positions);
    if (boundaries) requireDistinctPatches(*boundaries, walls.patchNames, walls.patchOf, walls.particles.positions, wallCells, dx);
    const GeneratedFluid<D> fluid =
        fillFluid(dict, lattice, walls, WallClearance<D>(walls, wallCells, dx), shapeDomain, initialPressure, properties, share, notes);
    if (boundaries) requireWallsFacingTheirFluid(*boundaries, walls, lattice, fluid.positions, share);

    const InitialState<D> state{properties, initialPressure};
    ParticleSet<D> fluidSet = fluidParticleSet(fluid, state, dx);
    fluidSet.globalId = serialIds(share, fluid.regionSizes);
    const double highestSurface = fluid.regionTops.empty() ? 0.0 : *std::max_element(fluid.regionTops.begin(), fluid.regionTops.end());
    ParticleSet<D> wallSet = wallParticleSet(walls, state, highestSurface, dx);

    StateHeader header;
    header.dimension = D;
    header.spacing = dx;
    header.domainMin.assign(lattice.lo.data(), lattice.lo.data() + D);
    header.domainMax.assign(lattice.hi.data(), lattice.hi.data() + D);
    header.periodic = lattice.periodic;
    dict.checkUnused();
    std::filesystem::create_directories(outputDirectory);
    // Walls first: the solver takes a time directory with a fluid state for a complete state.
    StateHeader wallHeader = header;
    wallHeader.patchNames = walls.patchNames;
    wallHeader.patchLayers = walls.patchLayers;
    const std::vector<double> totals = sumOverShares(share, {static_cast<double>(fluidSet.size()), static_cast<double>(fluid.dropped)});
    const GenerationSummary summary{D,    static_cast<std::size_t>(totals[0]), wallSet.size(), static_cast<std::size_t>(totals[1]), fluid.warnings,
                                    notes};
    if (!share) {
        writeParticleFile(outputDirectory / "walls.vtu", wallSet, wallHeader);
        writeParticleFile(outputDirectory / "fluid.vtu", fluidSet, header);
        return summary;
    }
    const auto rank = static_cast<std::size_t>(share->rows.rank), count = static_cast<std::size_t>(share->rows.count);
    std::vector<std::uint32_t> block(wallSet.size() * (rank + 1) / count - wallSet.size() * rank / count);
    std::iota(block.begin(), block.end(), static_cast<std::uint32_t>(wallSet.size() * rank / count));
    wallSet.keep(block);
    for (ParticleSet<D>* set : {&wallSet, &fluidSet}) addSerialPlaces(*set);
    writeParticlePiece(outputDirectory, "walls", share->rows.rank, share->rows.count, wallSet, wallHeader, share->together);
    writeParticlePiece(outputDirectory, "fluid", share->rows.rank, share->rows.count, fluidSet, header, share->together);
    return summary;
}

}  // namespace

GenerationSummary generateParticles(const std::filesystem::path& caseDirectory, bool overwrite, const GenerationShare* share) {
    const Dictionary dict = readCaseDictionary(caseDirectory, "system/generateParticlesDict");
    const std::filesystem::path output = caseDirectory / "0";
    const std::filesystem::path existing = stateFile(output, "fluid");
    if (!overwrite && std::filesystem::exists(existing))
        throw FatalError("error: '" + existing.string() + "' exists; remove it (./Allclean) or pass -overwrite");
    const bool first = !share || share->rows.rank == 0;
    // The state replaced, in either form: a .pvtu left beside a new .vtu would be read instead.
    const auto removeReplacedState = [&] {
        if (!first || !std::filesystem::exists(output)) return;
        for (const auto& entry : std::filesystem::directory_iterator(output)) {
            static const std::regex stateFileName(R"((fluid|walls)(_[0-9]+)?\.p?vtu)");
            if (std::regex_match(entry.path().filename().string(), stateFileName)) std::filesystem::remove(entry.path());
        }
    };
    share ? share->together(removeReplacedState) : removeReplacedState();
    const int dimension = dict.get<int>("dimension");
    GenerationSummary summary;
    switch (dimension) {
        case 1: summary = generate<1>(caseDirectory, dict, output, share); break;
        case 2: summary = generate<2>(caseDirectory, dict, output, share); break;
        case 3: summary = generate<3>(caseDirectory, dict, output, share); break;
        default: dict.fail("dimension", fmt::format("must be 1, 2 or 3, found {}", dimension));
    }
    // The later times of the state just replaced: the solver would resume from them.
    const auto removeLaterTimes = [&] {
        if (overwrite && first) removeTimeDirectories(timesAfter(caseDirectory, 0.0));
    };
    share ? share->together(removeLaterTimes) : removeLaterTimes();
    return summary;
}

}  // namespace sph
