#include "generation/WallPatches.hpp"

#include "generation/FluidRegions.hpp"
#include "generation/SurfaceShapes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sph {

namespace {

constexpr const char* faceNames[3][2] = {{"xMin", "xMax"}, {"yMin", "yMax"}, {"zMin", "zMax"}};

template <int D>
WallPatchParticles<D> boxWalls(const Dictionary& patch, double dx, int layers, double offset) {
    const Vec<D> lo = patch.getVector<D>("min"), hi = patch.getVector<D>("max");
    WallPatchParticles<D> walls;
    const std::array<LatticeAxis, D> axes = boxAxes<D>(patch, lo, hi, dx, walls.notes);
    std::array<std::array<bool, 2>, D> open{};
    if (patch.found("open")) {
        for (const std::string& face : patch.get<std::vector<std::string>>("open")) {
            bool known = false;
            for (int d = 0; d < D; ++d)
                for (int side = 0; side < 2; ++side)
                    if (face == faceNames[d][side]) open[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)] = known = true;
            if (!known) {
                std::string valid;
                for (int d = 0; d < D; ++d) valid += fmt::format(" {} {}", faceNames[d][0], faceNames[d][1]);
                patch.fail("open", fmt::format("unknown face '{}'; valid faces are:{}", face, valid));
            }
        }
    }
    std::array<int, D> index;
    for (int d = 0; d < D; ++d) index[static_cast<std::size_t>(d)] = -layers;
    while (true) {
        int depth = 0;
        bool skip = false;
        double faceArea = 1.0;  // the face's area a face particle stands for
        Vec<D> x, nearest;
        for (int d = 0; d < D; ++d) {
            const auto dd = static_cast<std::size_t>(d);
            const int i = index[dd];
            x[d] = axes[dd](i);
            nearest[d] = std::clamp(x[d], lo[d], hi[d]);
            if (i < 0) {
                depth = std::max(depth, -i);
                skip = skip || open[dd][0];
            } else if (i >= axes[dd].count) {
                depth = std::max(depth, i - axes[dd].count + 1);
                skip = skip || open[dd][1];
            } else {
                faceArea *= axes[dd].extent(i);
            }
        }
        if (depth > 0 && !skip) {
            // The lattice puts the first layer dx/2 outside the box; other offsets move it towards
            // the box along each axis it lies outside (onto the edges and corners for offset 0).
            const Vec<D> outside = nearest - x;
            Vec<D> shift = Vec<D>::Zero();
            int outsideAxes = 0;
            for (int d = 0; d < D; ++d)
                if (outside[d] != 0.0) {
                    shift[d] = std::copysign((0.5 - offset) * dx, outside[d]);
                    ++outsideAxes;
                }
            walls.add(x + shift, outside.normalized(), dx, depth - 1, outsideAxes == 1 ? faceArea : 0.0);
        }
        int d = 0;
        for (; d < D; ++d) {
            const auto dd = static_cast<std::size_t>(d);
            if (++index[dd] < axes[dd].count + layers) break;
            index[dd] = -layers;
        }
        if (d == D) break;
    }
    return walls;
}

// A solid box with the fluid outside: the lattice inside it, `layers` deep from each face, the
// normal pointing out of the nearest face (the mean of the faces at an edge or corner).
template <int D>
WallPatchParticles<D> boxObstacle(const Dictionary& patch, double dx, int layers, double offset) {
    const Vec<D> lo = patch.getVector<D>("min"), hi = patch.getVector<D>("max");
    WallPatchParticles<D> walls;
    const std::array<LatticeAxis, D> axes = boxAxes<D>(patch, lo, hi, dx, walls.notes);
    std::array<int, D> index{};
    while (true) {
        int depth = std::numeric_limits<int>::max();
        for (int d = 0; d < D; ++d) {
            const auto dd = static_cast<std::size_t>(d);
            depth = std::min({depth, index[dd], axes[dd].count - 1 - index[dd]});
        }
        if (depth < layers) {
            Vec<D> x, normal = Vec<D>::Zero();
            for (int d = 0; d < D; ++d) {
                const auto dd = static_cast<std::size_t>(d);
                x[d] = axes[dd](index[dd]);
                if (index[dd] == depth) normal[d] -= 1.0;
                if (axes[dd].count - 1 - index[dd] == depth) normal[d] += 1.0;
            }
            if (normal.squaredNorm() == 0.0) normal[0] = 1.0;  // a box one particle thick: any face
            normal.normalize();
            // The lattice puts the first layer dx/2 inside the box; shift along the normal for other offsets.
            walls.add(x - (offset - 0.5) * dx * normal, normal, dx, depth);
        }
        int d = 0;
        for (; d < D; ++d) {
            const auto dd = static_cast<std::size_t>(d);
            if (++index[dd] < axes[dd].count) break;
            index[dd] = 0;
        }
        if (d == D) break;
    }
    walls.solid = [lo, hi](const Vec<D>& x) { return (x.array() > lo.array()).all() && (x.array() < hi.array()).all(); };
    return walls;
}

// +1 when the normal is on the left of the direction of travel, -1 on the right.
double sideSign(const Dictionary& patch) {
    const std::string side = patch.getOrDefault<std::string>("side", "left");
    if (side != "left" && side != "right") patch.fail("side", "expected left or right, found '" + side + "'");
    return side == "left" ? 1.0 : -1.0;
}

WallPatchParticles<2> polyline(const Dictionary& patch, double dx, int layers, double offset) {
    const std::vector<Vec<2>> points = patch.getVectorList<2>("points");
    if (points.size() < 2) patch.fail("points", "a polyline needs at least 2 points");
    const double sign = sideSign(patch);
    WallPatchParticles<2> walls;
    for (std::size_t s = 0; s + 1 < points.size(); ++s) {
        const Vec<2> along = points[s + 1] - points[s];
        const double length = along.norm();
        if (!(length > 0.0)) patch.fail("points", fmt::format("points {} and {} coincide", s, s + 1));
        const Vec<2> tangent = along / length;
        const Vec<2> normal = sign * Vec<2>(-tangent.y(), tangent.x());
        const int n = std::max(1, static_cast<int>(std::lround(length / dx)));
        for (int layer = 0; layer < layers; ++layer)
            for (int k = 0; k < n; ++k)
                walls.add(points[s] + along * ((k + 0.5) / n) - (layer + offset) * dx * normal, normal, length / n, layer);
    }
    return walls;
}

// A closed polygon with a particle on every vertex (normal along the bisector of its two
// faces' normals) and equal spacing along each side.
WallPatchParticles<2> polygon(const Dictionary& patch, double dx, int layers, double offset) {
    const std::vector<Vec<2>> points = patch.getVectorList<2>("points");
    if (points.size() < 3) patch.fail("points", "a polygon needs at least 3 points");
    const double sign = sideSign(patch);
    const std::size_t m = points.size();
    std::vector<Vec<2>> faceNormal(m);
    std::vector<int> count(m);
    for (std::size_t s = 0; s < m; ++s) {
        const Vec<2> along = points[(s + 1) % m] - points[s];
        if (!(along.norm() > 0.0)) patch.fail("points", fmt::format("points {} and {} coincide", s, (s + 1) % m));
        faceNormal[s] = sign * Vec<2>(-along.y(), along.x()).normalized();
        count[s] = std::max(1, static_cast<int>(std::lround(along.norm() / dx)));
    }
    WallPatchParticles<2> walls;
    for (int layer = 0; layer < layers; ++layer) {
        const double distance = (layer + offset) * dx;
        for (std::size_t s = 0; s < m; ++s) {
            const Vec<2> along = points[(s + 1) % m] - points[s];
            const double faceSpacing = along.norm() / count[s];
            // The vertex: bisector normal, moved so both faces' offset lines pass through it.
            const std::size_t previous = (s + m - 1) % m;
            const Vec<2> bisector = (faceNormal[previous] + faceNormal[s]).normalized();
            const double previousSpacing = (points[s] - points[previous]).norm() / count[previous];
            const double vertexArea = (0.5 * previousSpacing * faceNormal[previous] + 0.5 * faceSpacing * faceNormal[s]).norm();
            walls.add(points[s] - distance / bisector.dot(faceNormal[s]) * bisector, bisector, 0.5 * (previousSpacing + faceSpacing), layer, vertexArea);
            for (int k = 1; k < count[s]; ++k)
                walls.add(points[s] + along * (static_cast<double>(k) / count[s]) - distance * faceNormal[s], faceNormal[s], faceSpacing, layer);
        }
    }
    return walls;
}

WallPatchParticles<2> ellipse(const Dictionary& patch, double dx, int layers, double offset) {
    const Vec<2> centre = patch.getVector<2>("centre");
    Vec<2> axes;
    if (patch.found("radius")) {
        axes.setConstant(patch.getPositive("radius"));
    } else {
        axes = patch.getVector<2>("semiAxes");
        if (!(axes.minCoeff() > 0.0)) patch.fail("semiAxes", "both semi-axes must be greater than zero");
    }
    const bool fluidInside = patch.get<bool>("fluidInside");
    // Arc length along the ellipse from a fine polygon, then particles at equal arc steps.
    constexpr int fine = 20000;
    std::vector<double> arc(fine + 1, 0.0);
    const auto point = [&](double theta) { return Vec<2>(axes.x() * std::cos(theta), axes.y() * std::sin(theta)); };
    for (int k = 1; k <= fine; ++k) arc[k] = arc[k - 1] + (point(2 * std::numbers::pi * k / fine) - point(2 * std::numbers::pi * (k - 1) / fine)).norm();
    const double perimeter = arc.back();
    WallPatchParticles<2> walls;
    for (int layer = 0; layer < layers; ++layer) {
        const double distance = (layer + offset) * dx;
        // Each layer keeps about dx between neighbours: its perimeter grows or shrinks with the offset.
        const double layerPerimeter = perimeter + (fluidInside ? 1.0 : -1.0) * 2.0 * std::numbers::pi * distance;
        const int n = std::max(3, static_cast<int>(std::lround(layerPerimeter / dx)));
        for (int k = 0; k < n; ++k) {
            const double target = (k + 0.5) * perimeter / n;
            const auto it = std::lower_bound(arc.begin(), arc.end(), target);
            const long m = std::clamp<long>(it - arc.begin(), 1, fine);
            const double fraction = (target - arc[m - 1]) / (arc[m] - arc[m - 1]);
            const double theta = 2 * std::numbers::pi * (m - 1 + fraction) / fine;
            const Vec<2> onCurve = point(theta);
            const Vec<2> outward = Vec<2>(onCurve.x() / (axes.x() * axes.x()), onCurve.y() / (axes.y() * axes.y())).normalized();
            const Vec<2> intoFluid = fluidInside ? Vec<2>(-outward) : outward;
            walls.add(centre + onCurve - distance * intoFluid, intoFluid, layerPerimeter / n, layer);
        }
    }
    if (!fluidInside)
        walls.solid = [centre, axes](const Vec<2>& x) {
            return std::pow((x.x() - centre.x()) / axes.x(), 2) + std::pow((x.y() - centre.y()) / axes.y(), 2) < 1.0;
        };
    return walls;
}

}  // namespace

WallLayout wallLayout(const Dictionary& patch, const std::function<WallLayout()>& fromModel) {
    if (!patch.found("layers")) {
        WallLayout layout = fromModel();
        if (patch.found("firstLayerOffset")) layout.firstLayerOffset = patch.getNonNegative("firstLayerOffset");
        return layout;
    }
    const int layers = patch.get<int>("layers");
    // A kernel support needs a few layers; thousands would be a slip that fills the memory.
    constexpr int maxLayers = 1000;
    if (layers < 1 || layers > maxLayers) patch.fail("layers", fmt::format("must be from 1 to {}, found {}", maxLayers, layers));
    return {layers, patch.getNonNegativeOrDefault("firstLayerOffset", 0.5)};
}

template <int D>
WallPatchParticles<D> generateWallPatch(const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>& domain) {
    const std::string type = patch.get<std::string>("type");
    const int layers = layout.layers;
    const double offset = layout.firstLayerOffset;
    if constexpr (D == 3)
        if (type == "surface") return surfaceWalls(patch, dx, layout, domain.caseDirectory, domain.min, domain.max);
    if (type == "boxWalls") return boxWalls<D>(patch, dx, layers, offset);
    if (type == "box") return boxObstacle<D>(patch, dx, layers, offset);
    if constexpr (D == 2) {
        if (type == "polyline") return polyline(patch, dx, layers, offset);
        if (type == "polygon") return polygon(patch, dx, layers, offset);
        if (type == "ellipse" || type == "circle") return ellipse(patch, dx, layers, offset);
    }
    const std::string valid = D == 2 ? "box, boxWalls, circle, ellipse, polygon, polyline" : D == 3 ? "box, boxWalls, surface" : "box, boxWalls";
    throw FatalError(patch.entry("type").tokens().front().where,
                     fmt::format("unknown wall patch type '{}' for a {}D case; valid types are: {}", type, D, valid));
}

template WallPatchParticles<1> generateWallPatch<1>(const Dictionary&, double, const WallLayout&, const GenerationDomain<1>&);
template WallPatchParticles<2> generateWallPatch<2>(const Dictionary&, double, const WallLayout&, const GenerationDomain<2>&);
template WallPatchParticles<3> generateWallPatch<3>(const Dictionary&, double, const WallLayout&, const GenerationDomain<3>&);

}  // namespace sph
