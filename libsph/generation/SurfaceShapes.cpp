#include "generation/SurfaceShapes.hpp"

#include "io/ClosedCurves.hpp"
#include "io/TriangleSurface.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <tuple>
#include <numbers>
#include <vector>

namespace sph {

namespace {

// The closed surface (3D) or curves (2D) a dictionary's `file` names, scaled by `scale`; 2D
// cuts a surface at z = `slice`. A reading error is reported at the `file` keyword.
template <int D>
auto readBoundary(const Dictionary& dict, const std::filesystem::path& caseDirectory) {
    const std::filesystem::path file = caseDirectory / dict.get<std::string>("file");
    const double scale = dict.getPositiveOrDefault("scale", 1.0);
    try {
        if constexpr (D == 2)
            return std::make_shared<const ClosedCurves>(ClosedCurves::read(file, scale, dict.getOrDefault<double>("slice", 0.0)));
        else
            return std::make_shared<const TriangleSurface>(TriangleSurface::read(file, scale));
    } catch (const FatalError& error) {
        dict.fail("file", error.what());
    }
}

// A curve's vertices resampled at about dx along it: its corners (vertices turning by more
// than cornerTurn) kept, and each stretch between two corners divided into equal lengths
// (the whole loop from its first vertex when it has none), so a finely tessellated curve
// gives one particle per spacing and a polygon keeps its vertices.
constexpr double cornerTurn = 20.0 * std::numbers::pi / 180.0;

std::vector<Vec<2>> resampleLoop(const std::vector<Vec<2>>& loop, double dx) {
    const std::size_t n = loop.size();
    std::vector<std::size_t> corners;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec<2> in = (loop[i] - loop[(i + n - 1) % n]).normalized(), out = (loop[(i + 1) % n] - loop[i]).normalized();
        if (std::acos(std::clamp(in.dot(out), -1.0, 1.0)) > cornerTurn) corners.push_back(i);
    }
    if (corners.empty()) corners.push_back(0);
    std::vector<Vec<2>> resampled;
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const std::size_t from = corners[c], to = corners[(c + 1) % corners.size()];
        std::vector<Vec<2>> stretch{loop[from]};
        for (std::size_t i = (from + 1) % n;; i = (i + 1) % n) {
            stretch.push_back(loop[i]);
            if (i == to) break;
        }
        std::vector<double> arc{0.0};
        for (std::size_t i = 1; i < stretch.size(); ++i) arc.push_back(arc.back() + (stretch[i] - stretch[i - 1]).norm());
        const long pieces = std::max(1L, std::lround(arc.back() / dx));
        std::size_t segment = 1;
        for (long p = 0; p < pieces; ++p) {
            const double s = arc.back() * static_cast<double>(p) / static_cast<double>(pieces);
            while (segment + 1 < arc.size() && arc[segment] < s) ++segment;
            const double t = arc[segment] > arc[segment - 1] ? (s - arc[segment - 1]) / (arc[segment] - arc[segment - 1]) : 0.0;
            resampled.push_back(stretch[segment - 1] + t * (stretch[segment] - stretch[segment - 1]));
        }
    }
    return resampled;
}

// Visits the domain's lattice points (anchored at its min corner) within [lower, upper], of the
// share's rows.
template <int D>
void forEachLatticePointWithin(const Vec<D>& domainMin, const Vec<D>& domainMax, double dx, const Vec<D>& lower, const Vec<D>& upper,
                               const std::function<void(const Vec<D>&)>& visit, const LatticeShare& share = {}) {
    std::array<long, 3> first{}, last{};
    for (int d = 0; d < D; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        const long cells = static_cast<long>(std::floor((domainMax[d] - domainMin[d]) / dx));
        first[dd] = std::clamp(static_cast<long>(std::floor((lower[d] - domainMin[d]) / dx - 0.5)), 0L, cells);
        last[dd] = std::clamp(static_cast<long>(std::ceil((upper[d] - domainMin[d]) / dx - 0.5)), 0L, cells - 1);
    }
    constexpr auto slowest = static_cast<std::size_t>(D - 1);
    std::tie(first[slowest], last[slowest]) = share.rows(first[slowest], last[slowest]);
    for (long k = first[2]; k <= last[2]; ++k)
        for (long j = first[1]; j <= last[1]; ++j)
            for (long i = first[0]; i <= last[0]; ++i) {
                const Vec<3> index(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5, static_cast<double>(k) + 0.5);
                visit(domainMin + dx * index.head<D>());
            }
}

// Halves a triangle across its longest edge until no edge is longer than `longest`, and visits
// each piece's centroid and area: pieces of any triangle, however thin, are then at most
// `longest` across (a right isosceles piece of 2 dx: dx^2 / 2 to dx^2).
void forEachPieceOf(const Triangle& triangle, double longest, const std::function<void(const Vec<3>&, double)>& visit) {
    std::vector<std::array<Vec<3>, 3>> pieces{{triangle.a, triangle.b, triangle.c}};
    while (!pieces.empty()) {
        const std::array<Vec<3>, 3> p = pieces.back();
        pieces.pop_back();
        std::size_t edge = 0;  // the edge from p[edge] to p[edge + 1]
        double length2 = 0.0;
        for (std::size_t k = 0; k < 3; ++k)
            if (const double l2 = (p[(k + 1) % 3] - p[k]).squaredNorm(); l2 > length2) {
                length2 = l2;
                edge = k;
            }
        if (length2 <= longest * longest) {
            visit((p[0] + p[1] + p[2]) / 3.0, 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm());
            continue;
        }
        const Vec<3> middle = 0.5 * (p[edge] + p[(edge + 1) % 3]);
        pieces.push_back({p[edge], middle, p[(edge + 2) % 3]});
        pieces.push_back({middle, p[(edge + 1) % 3], p[(edge + 2) % 3]});
    }
}

// Visits the points of the domain's lattice, projected along the axis the triangle faces most
// (its normal's largest component), that fall inside the triangle's projection, lifted onto
// the triangle. On a plane facing an axis they are the lattice's own columns; each stands for
// the lattice cell's projected area dx^2 / |n_axis|. A point on an edge two triangles share
// belongs to one of them (the top-left rule of rasterisers), and a triangle narrower than the
// lattice may hold none.
void forEachLatticePointOn(const Triangle& triangle, const Vec<3>& domainMin, double dx, const std::function<void(const Vec<3>&, double)>& visit) {
    int axis = 0;
    triangle.outward.cwiseAbs().maxCoeff(&axis);
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::array<Vec<2>, 3> corner{Vec<2>(triangle.a[u], triangle.a[v]), Vec<2>(triangle.b[u], triangle.b[v]), Vec<2>(triangle.c[u], triangle.c[v])};
    const auto cross = [](const Vec<2>& p, const Vec<2>& q) { return p.x() * q.y() - p.y() * q.x(); };
    if (cross(corner[1] - corner[0], corner[2] - corner[0]) < 0.0) std::swap(corner[1], corner[2]);  // counter-clockwise
    const auto owns = [&](int edge, const Vec<2>& p) {
        const Vec<2>& from = corner[static_cast<std::size_t>(edge)];
        const Vec<2>& to = corner[static_cast<std::size_t>((edge + 1) % 3)];
        // Evaluated from the edge's lexicographically lower end, so that the two triangles
        // sharing it get the same number, of opposite sign, whatever the rounding.
        const bool reversed = std::lexicographical_compare(to.data(), to.data() + 2, from.data(), from.data() + 2);
        const Vec<2>& base = reversed ? to : from;
        const double side = (reversed ? -1.0 : 1.0) * cross((reversed ? from : to) - base, p - base);
        const Vec<2> along = to - from;
        return side > 0.0 || (side == 0.0 && (along.y() < 0.0 || (along.y() == 0.0 && along.x() > 0.0)));
    };
    const double area = dx * dx / std::abs(triangle.outward[axis]);
    const Vec<2> lower = corner[0].cwiseMin(corner[1]).cwiseMin(corner[2]), upper = corner[0].cwiseMax(corner[1]).cwiseMax(corner[2]);
    const auto firstIndex = [&](double lo, double origin) { return static_cast<long>(std::ceil((lo - origin) / dx - 0.5)); };
    for (long i = firstIndex(lower.x(), domainMin[u]); domainMin[u] + (static_cast<double>(i) + 0.5) * dx <= upper.x(); ++i)
        for (long j = firstIndex(lower.y(), domainMin[v]); domainMin[v] + (static_cast<double>(j) + 0.5) * dx <= upper.y(); ++j) {
            const Vec<2> p(domainMin[u] + (static_cast<double>(i) + 0.5) * dx, domainMin[v] + (static_cast<double>(j) + 0.5) * dx);
            if (!owns(0, p) || !owns(1, p) || !owns(2, p)) continue;
            Vec<3> x;
            x[u] = p.x();
            x[v] = p.y();
            // On the triangle's plane: n . (x - a) = 0 solved for the facing axis.
            x[axis] = triangle.a[axis] -
                      (triangle.outward[u] * (p.x() - triangle.a[u]) + triangle.outward[v] * (p.y() - triangle.a[v])) / triangle.outward[axis];
            visit(x, area);
        }
}

}  // namespace

// A lattice point this close to the surface lies on it (a flat face through lattice points:
// a slope of 45 degrees, a plane at a lattice coordinate). It belongs to the wall, not the
// fluid, so that the two never hold the same point.
constexpr double onSurfaceTolerance = 1e-9;  // in spacings

template <class Surface, int D>
bool onSurface(const Surface& surface, const Vec<D>& x, double dx) {
    Vec<D> closest;
    return surface.distance(x, closest) < onSurfaceTolerance * dx;
}

// The unit normal into the fluid at a lattice point on the surface, where the closest point
// gives no direction: the gradient of the signed distance (negative inside), sampled
// 1e-3 dx either side along each axis.
template <class Surface, int D>
Vec<D> normalOnSurface(const Surface& surface, const Vec<D>& x, double dx, bool fluidInside) {
    const double step = 1e-3 * dx;
    const auto signedDistance = [&](const Vec<D>& y) {
        Vec<D> closest;
        const double distance = surface.distance(y, closest);
        return surface.inside(y) ? -distance : distance;
    };
    Vec<D> gradient;
    for (int d = 0; d < D; ++d) {
        const Vec<D> offset = step * Vec<D>::Unit(d);
        gradient[d] = signedDistance(x + offset) - signedDistance(x - offset);
    }
    return (fluidInside ? -1.0 : 1.0) * gradient.normalized();
}

template <int D>
std::vector<Vec<D>> fillSurface(const Dictionary& region, double dx, const GenerationDomain<D>& domain) {
    const auto surface = readBoundary<D>(region, domain.caseDirectory);
    std::vector<Vec<D>> points;
    forEachLatticePointWithin<D>(
        domain.min, domain.max, dx, surface->lower(), surface->upper(),
        [&](const Vec<D>& x) {
            if (surface->inside(x) && !onSurface(*surface, x, dx)) points.push_back(x);
        },
        domain.share);
    return points;
}

namespace {

// One layer of a 2D surface: each curve resampled at about dx, as a polygon's wall.
WallPatchParticles<2> sampledWall(const Dictionary& patch, const ClosedCurves& curves, bool fluidInside, double dx, double offset) {
    WallPatchParticles<2> walls;
    // Each loop runs counter-clockwise: fluid inside it is on the left.
    for (const std::vector<Vec<2>>& loop : curves.loops())
        addWallPath(patch, resampleLoop(loop, dx), true, fluidInside ? 1.0 : -1.0, dx, 1, offset, walls);
    return walls;
}

// One layer of a 3D surface: triangle by triangle.
WallPatchParticles<3> sampledWall(const TriangleSurface& surface, bool fluidInside, const Vec<3>& domainMin, double dx, double offset) {
    WallPatchParticles<3> walls;
    for (const Triangle& t : surface.triangles()) {
        const Vec<3> intoFluid = fluidInside ? Vec<3>(-t.outward) : t.outward;
        const auto add = [&](const Vec<3>& x, double area) { walls.add(x - offset * dx * intoFluid, intoFluid, std::sqrt(area), 0, area); };
        // A plane facing an axis takes the lattice's own points, as a box's face; any other
        // triangle its pieces, whose areas add up to its own.
        if (t.outward.cwiseAbs().maxCoeff() > 1.0 - 1e-9)
            forEachLatticePointOn(t, domainMin, dx, add);
        else
            forEachPieceOf(t, 2.0 * dx, add);
    }
    return walls;
}

}  // namespace

template <int D>
WallPatchParticles<D> surfaceWalls(const Dictionary& patch, double dx, const WallLayout& layout, const std::filesystem::path& caseDirectory,
                                   const Vec<D>& domainMin, const Vec<D>& domainMax) {
    const int layers = layout.layers;
    const auto surface = readBoundary<D>(patch, caseDirectory);
    const bool fluidInside = patch.get<bool>("fluidInside");
    WallPatchParticles<D> walls;
    if (layers == 1) {
        if constexpr (D == 2)
            walls = sampledWall(patch, *surface, fluidInside, dx, layout.firstLayerOffset);
        else
            walls = sampledWall(*surface, fluidInside, domainMin, dx, layout.firstLayerOffset);
    } else {
        if (patch.found("firstLayerOffset"))
            patch.fail("firstLayerOffset", fmt::format("a surface's wall of {} layers is the lattice behind the surface, which no offset moves; "
                                                       "it applies to one layer (layers 1;)",
                                                       layers));
        const Vec<D> margin = Vec<D>::Constant(layers * dx);
        forEachLatticePointWithin<D>(domainMin, domainMax, dx, surface->lower() - margin, surface->upper() + margin, [&](const Vec<D>& x) {
            Vec<D> closest;
            const double distance = surface->distance(x, closest);
            if (distance < onSurfaceTolerance * dx) {
                walls.add(x, normalOnSurface(*surface, x, dx, fluidInside), dx, 0);
                return;
            }
            if (surface->inside(x) == fluidInside || !(distance < layers * dx)) return;
            walls.add(x, (closest - x) / distance, dx, std::min(layers - 1, static_cast<int>(distance / dx)));
        });
    }
    if (walls.positions.empty()) patch.fail("file", "the surface makes no wall particle inside the domain");
    if (!fluidInside) walls.solid = [surface](const Vec<D>& x) { return surface->inside(x); };
    return walls;
}

template std::vector<Vec<2>> fillSurface<2>(const Dictionary&, double, const GenerationDomain<2>&);
template std::vector<Vec<3>> fillSurface<3>(const Dictionary&, double, const GenerationDomain<3>&);
template WallPatchParticles<2> surfaceWalls<2>(const Dictionary&, double, const WallLayout&, const std::filesystem::path&, const Vec<2>&,
                                               const Vec<2>&);
template WallPatchParticles<3> surfaceWalls<3>(const Dictionary&, double, const WallLayout&, const std::filesystem::path&, const Vec<3>&,
                                               const Vec<3>&);

}  // namespace sph
