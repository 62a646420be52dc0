#include "generation/SurfaceShapes.hpp"

#include "io/TriangleSurface.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace sph {

namespace {

std::shared_ptr<const TriangleSurface> readSurface(const Dictionary& dict, const std::filesystem::path& caseDirectory) {
    const std::string file = dict.get<std::string>("file");
    const double scale = dict.getPositiveOrDefault("scale", 1.0);
    try {
        return std::make_shared<const TriangleSurface>(TriangleSurface::read(caseDirectory / file, scale));
    } catch (const FatalError& error) {
        dict.fail("file", error.what());
    }
}

// Visits the domain's lattice points (anchored at its min corner) within [lower, upper].
void forEachLatticePointWithin(const Vec<3>& domainMin, const Vec<3>& domainMax, double dx, const Vec<3>& lower, const Vec<3>& upper,
                               const std::function<void(const Vec<3>&)>& visit) {
    std::array<long, 3> first, last;
    for (int d = 0; d < 3; ++d) {
        const auto dd = static_cast<std::size_t>(d);
        const long cells = static_cast<long>(std::floor((domainMax[d] - domainMin[d]) / dx));
        first[dd] = std::clamp(static_cast<long>(std::floor((lower[d] - domainMin[d]) / dx - 0.5)), 0L, cells);
        last[dd] = std::clamp(static_cast<long>(std::ceil((upper[d] - domainMin[d]) / dx - 0.5)), 0L, cells - 1);
    }
    for (long k = first[2]; k <= last[2]; ++k)
        for (long j = first[1]; j <= last[1]; ++j)
            for (long i = first[0]; i <= last[0]; ++i)
                visit(domainMin + dx * Vec<3>(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5, static_cast<double>(k) + 0.5));
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
            x[axis] = triangle.a[axis] - (triangle.outward[u] * (p.x() - triangle.a[u]) + triangle.outward[v] * (p.y() - triangle.a[v])) /
                                             triangle.outward[axis];
            visit(x, area);
        }
}

}  // namespace

std::vector<Vec<3>> fillSurface(const Dictionary& region, double dx, const std::filesystem::path& caseDirectory, const Vec<3>& domainMin,
                                const Vec<3>& domainMax) {
    const std::shared_ptr<const TriangleSurface> surface = readSurface(region, caseDirectory);
    std::vector<Vec<3>> points;
    forEachLatticePointWithin(domainMin, domainMax, dx, surface->lower(), surface->upper(), [&](const Vec<3>& x) {
        if (surface->inside(x)) points.push_back(x);
    });
    return points;
}

WallPatchParticles<3> surfaceWalls(const Dictionary& patch, double dx, const WallLayout& layout, const std::filesystem::path& caseDirectory,
                                   const Vec<3>& domainMin, const Vec<3>& domainMax) {
    const int layers = layout.layers;
    const std::shared_ptr<const TriangleSurface> surface = readSurface(patch, caseDirectory);
    const bool fluidInside = patch.get<bool>("fluidInside");
    WallPatchParticles<3> walls;
    if (layers == 1) {
        const double offset = layout.firstLayerOffset;
        for (const Triangle& t : surface->triangles()) {
            const Vec<3> intoFluid = fluidInside ? Vec<3>(-t.outward) : t.outward;
            const auto add = [&](const Vec<3>& x, double area) { walls.add(x - offset * dx * intoFluid, intoFluid, std::sqrt(area), 0, area); };
            // A plane facing an axis takes the lattice's own points, as a box's face; any other
            // triangle its pieces, whose areas add up to its own.
            if (t.outward.cwiseAbs().maxCoeff() > 1.0 - 1e-9) forEachLatticePointOn(t, domainMin, dx, add);
            else forEachPieceOf(t, 2.0 * dx, add);
        }
    } else {
        if (patch.found("firstLayerOffset"))
            patch.fail("firstLayerOffset", fmt::format("a surface's wall of {} layers is the lattice behind the surface, which no offset moves; "
                                                       "it applies to one layer (layers 1;)",
                                                       layers));
        const Vec<3> margin = Vec<3>::Constant(layers * dx);
        forEachLatticePointWithin(domainMin, domainMax, dx, surface->lower() - margin, surface->upper() + margin, [&](const Vec<3>& x) {
            if (surface->inside(x) == fluidInside) return;
            Vec<3> closest;
            const double distance = surface->distance(x, closest);
            if (!(distance < layers * dx) || !(distance > 0.0)) return;
            walls.add(x, (closest - x) / distance, dx, std::min(layers - 1, static_cast<int>(distance / dx)));
        });
    }
    if (walls.positions.empty()) patch.fail("file", "the surface makes no wall particle inside the domain");
    if (!fluidInside) walls.solid = [surface](const Vec<3>& x) { return surface->inside(x); };
    return walls;
}

}  // namespace sph
