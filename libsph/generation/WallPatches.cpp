#include "generation/WallPatches.hpp"

#include "core/PlaneLoop.hpp"
#include "generation/FluidRegions.hpp"
#include "generation/SurfaceShapes.hpp"
#include "io/SelectByType.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <numbers>
#include <optional>

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
    const int thinnest =
        std::min_element(axes.begin(), axes.end(), [](const LatticeAxis& a, const LatticeAxis& b) { return a.count < b.count; })->count;
    walls.filledThrough = thinnest < 2 * layers && thinnest >= layers;
    if (thinnest < 2 * layers)
        walls.notes.push_back(walls.filledThrough
                                  ? fmt::format("the layers from its faces meet inside it, where it is thinner than twice its {} layers", layers)
                                  : fmt::format("thinner than its {} layers: it holds {} behind each face, and the fluid on its "
                                                "sides reach each other through it",
                                                layers, (thinnest + 1) / 2));
    return walls;
}

// +1 when the normal is on the left of the direction of travel, -1 on the right.
double sideSign(const Dictionary& patch) {
    const std::string side = patch.getOrDefault<std::string>("side", "left");
    if (side != "left" && side != "right") patch.fail("side", "expected left or right, found '" + side + "'");
    return side == "left" ? 1.0 : -1.0;
}

// One straight face of a 2D wall path (polyline or polygon), divided into `count` equal spacings.
struct PathFace {
    Vec<2> start, along, tangent, normal;
    double length, spacing;
    int count;

    // The point `spacings` spacings from the start, `depth` behind the face.
    Vec<2> at(double spacings, double depth) const { return start + along * (spacings / count) - depth * normal; }
};

std::vector<PathFace> pathFaces(const Dictionary& patch, const std::vector<Vec<2>>& points, bool closed, double sign, double dx) {
    const std::size_t m = points.size(), faces = closed ? m : m - 1;
    std::vector<PathFace> path;
    for (std::size_t s = 0; s < faces; ++s) {
        const Vec<2> along = points[(s + 1) % m] - points[s];
        const double length = along.norm();
        if (!(length > 0.0)) patch.fail("points", fmt::format("points {} and {} coincide", s, (s + 1) % m));
        const Vec<2> tangent = along / length;
        const int count = std::max(1, static_cast<int>(std::lround(length / dx)));
        path.push_back({points[s], along, tangent, sign * Vec<2>(-tangent.y(), tangent.x()), length, length / count, count});
    }
    return path;
}

// A layer `depth` behind the corner where face `a` meets face `b`, when face b turns towards the
// fluid (the wall's side is convex): the two faces' offset lines leave a gap behind the corner.
// It is filled at about dx along a path from face a's nearest particle (`gapA` before the
// corner) to face b's (`gapB` after it): up to a right angle the offset lines extended to where
// they meet (the mitre), which gives a right-angled corner the block the faces' lattices
// continue; beyond, an arc of radius `depth` round the corner, so no particle lies farther
// than `depth` from the wall.
void fillConvexCorner(const PathFace& a, const PathFace& b, double depth, double gapA, double gapB, double dx, int layer,
                      WallPatchParticles<2>& walls) {
    const Vec<2> corner = b.start, behindA = corner - depth * a.normal, behindB = corner - depth * b.normal;
    const double turn = std::acos(std::clamp(a.tangent.dot(b.tangent), -1.0, 1.0));
    const bool mitre = turn <= 0.5 * std::numbers::pi + 1e-12;
    const double extension = depth * std::tan(0.5 * turn);
    const double join = mitre ? 2.0 * extension : depth * turn, path = gapA + join + gapB;
    const double turnSense = a.normal.x() * b.normal.y() - a.normal.y() * b.normal.x() > 0.0 ? 1.0 : -1.0;
    const long inserted = std::lround(path / dx) - 1;
    const double step = path / static_cast<double>(inserted + 1);
    for (long k = 1; k <= inserted; ++k) {
        const double u = static_cast<double>(k) * step - gapA;  // from the point behind the corner on a's line
        if (u <= 0.0) {
            walls.add(behindA + u * a.tangent, a.normal, step, layer);
        } else if (u >= join) {
            walls.add(behindB + (u - join) * b.tangent, b.normal, step, layer);
        } else {
            // Past both faces' ends the nearest point of the wall is the corner: the normal
            // points to it, as in boxWalls' corners.
            Vec<2> x;
            if (!mitre) {
                const double angle = turnSense * u / depth;
                const Vec<2> outward = -a.normal;
                x = corner + depth * Vec<2>(std::cos(angle) * outward.x() - std::sin(angle) * outward.y(),
                                            std::sin(angle) * outward.x() + std::cos(angle) * outward.y());
            } else {
                x = u < extension ? Vec<2>(behindA + u * a.tangent) : Vec<2>(behindB - (join - u) * b.tangent);
            }
            walls.add(x, (corner - x).normalized(), step, layer);
        }
    }
}

// A particle of one face of a wall path, before the corners are resolved.
struct PathParticle {
    Vec<2> x, normal;
    double spacing, area, depth;
    int layer;
    bool kept = true;
};

// How deep x lies behind `face`, or nothing when it is not level with the face (beyond its ends).
std::optional<double> depthBehind(const Vec<2>& x, const PathFace& face, double dx) {
    const Vec<2> relative = x - face.start;
    const double along = relative.dot(face.tangent);
    if (along < -1e-9 * dx || along > face.length + 1e-9 * dx) return std::nullopt;
    return -relative.dot(face.normal);
}

// Where the wall's side of the corner between faces a and b is concave, their layers overlap:
// each particle belongs to the face it lies nearer (b on a tie), and a particle of a closer
// than 3/4 dx to one of b's is left out, as is any that would come out in front of the other
// face (a wedge thinner than the layers). A right-angled corner keeps its lattice, each point once.
void resolveConcaveCorner(const PathFace& a, std::vector<PathParticle>& ofA, const PathFace& b, std::vector<PathParticle>& ofB, double deepest,
                          double dx) {
    const double tolerance = 1e-9 * dx;
    std::vector<Vec<2>> nearCorner;  // b's particles within reach of a's layers
    for (PathParticle& p : ofB) {
        const std::optional<double> behindA = depthBehind(p.x, a, dx);
        if (!p.kept || !behindA || !(p.depth > 0.0)) continue;
        if (*behindA < p.depth - tolerance)
            p.kept = false;
        else if (*behindA < deepest + dx)
            nearCorner.push_back(p.x);
    }
    for (PathParticle& p : ofA) {
        const std::optional<double> behindB = depthBehind(p.x, b, dx);
        if (!p.kept || !behindB || !(p.depth > 0.0)) continue;
        p.kept = *behindB > p.depth + tolerance &&
                 std::none_of(nearCorner.begin(), nearCorner.end(), [&](const Vec<2>& y) { return (y - p.x).norm() < 0.75 * dx; });
    }
}

}  // namespace

// The layers of a 2D wall path. Each face's particles sit at its spacings' centres (polyline)
// or, on a polygon, at its spacings' ends with one on each vertex (bisector normal, standing
// for half of each adjacent spacing). At a vertex, a layer behind the wall fills the gap where
// the wall's side is convex (fillConvexCorner) and drops the overlap where it is concave
// (resolveConcaveCorner); layers on the wall surface are left as they are.
void addWallPath(const Dictionary& patch, const std::vector<Vec<2>>& points, bool closed, double sign, double dx, int layers, double offset,
                 WallPatchParticles<2>& walls) {
    const std::vector<PathFace> faces = pathFaces(patch, points, closed, sign, dx);
    const std::size_t m = faces.size();
    const auto convex = [](const PathFace& a, const PathFace& b) { return b.tangent.dot(a.normal) > 0.0; };
    const double firstPoint = closed ? 0.0 : 0.5;  // in spacings from the face's start
    const double cornerGap = 1.0 - firstPoint;     // in spacings: from a corner to the nearest particle of each face
    // Each face's particles, layer by layer; on a polygon the vertex at its start comes first
    // (where the wall's side is convex the corner's fill takes its place).
    std::vector<std::vector<PathParticle>> ofFace(m);
    for (std::size_t s = 0; s < m; ++s) {
        const PathFace& face = faces[s];
        const PathFace& previous = faces[(s + m - 1) % m];
        for (int layer = 0; layer < layers; ++layer) {
            const double depth = (layer + offset) * dx;
            if (closed && (!(depth > 0.0) || !convex(previous, face))) {
                const Vec<2> bisector = (previous.normal + face.normal).normalized();
                const double vertexArea = (0.5 * previous.spacing * previous.normal + 0.5 * face.spacing * face.normal).norm();
                ofFace[s].push_back({face.start - depth / bisector.dot(face.normal) * bisector, bisector, 0.5 * (previous.spacing + face.spacing),
                                     vertexArea, depth, layer});
            }
            for (int k = closed ? 1 : 0; k < face.count; ++k)
                ofFace[s].push_back({face.at(k + firstPoint, depth), face.normal, face.spacing, face.spacing, depth, layer});
        }
    }
    const std::size_t corners = closed ? m : m - 1;
    const double deepest = (layers - 1 + offset) * dx;
    for (std::size_t s = 0; s < corners; ++s)
        if (!convex(faces[s], faces[(s + 1) % m])) resolveConcaveCorner(faces[s], ofFace[s], faces[(s + 1) % m], ofFace[(s + 1) % m], deepest, dx);
    for (int layer = 0; layer < layers; ++layer) {
        const double depth = (layer + offset) * dx;
        for (std::size_t s = 0; s < m; ++s) {
            for (const PathParticle& p : ofFace[s])
                if (p.layer == layer && p.kept) walls.add(p.x, p.normal, p.spacing, layer, p.area);
            const PathFace& next = faces[(s + 1) % m];
            if (s < corners && depth > 0.0 && convex(faces[s], next))
                fillConvexCorner(faces[s], next, depth, cornerGap * faces[s].spacing, cornerGap * next.spacing, dx, layer, walls);
        }
    }
}

namespace {

// A solid body thinner than twice its layers: the layers laid from its faces meet inside it and,
// where it is thinner than its layers, the deeper ones pass out of its far side into the fluid
// (a 2 dx plate with dummy particles' three layers put its third layers among the fluid on
// either side, and the run blew up). Keeps the particles inside the solid or on its surface and,
// of any two on one place (closer than dx/10: a solid a whole number of spacings thick lays
// the layers of opposite faces on one another), the one of the lower layer (the first laid on a
// tie), with a note of how many went.
void keepWithinSolid(WallPatchParticles<2>& walls, double dx) {
    std::vector<std::size_t> order(walls.positions.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return walls.layers[a] < walls.layers[b]; });
    const double cell = 0.1 * dx;
    const auto cellOf = [&](const Vec<2>& x) { return std::pair{std::lround(std::floor(x.x() / cell)), std::lround(std::floor(x.y() / cell))}; };
    std::map<std::pair<long, long>, std::vector<Vec<2>>> kept;
    const auto crowded = [&](const Vec<2>& x) {
        const auto [cx, cy] = cellOf(x);
        for (long i = cx - 1; i <= cx + 1; ++i)
            for (long j = cy - 1; j <= cy + 1; ++j)
                if (const auto it = kept.find({i, j}); it != kept.end())
                    for (const Vec<2>& y : it->second)
                        if ((y - x).norm() < 0.1 * dx) return true;
        return false;
    };
    WallPatchParticles<2> within;
    within.solid = walls.solid;
    within.notes = walls.notes;
    std::vector<bool> keep(order.size(), false);
    std::size_t outside = 0;
    for (const std::size_t k : order) {
        const Vec<2>& x = walls.positions[k];
        // Just behind the particle, so that one on the surface counts as inside.
        if (!walls.solid(x - 1e-6 * dx * walls.normals[k])) {
            ++outside;
            continue;
        }
        if (crowded(x)) continue;
        keep[k] = true;
        kept[cellOf(x)].push_back(x);
    }
    for (std::size_t k = 0; k < keep.size(); ++k)
        if (keep[k]) within.add(walls.positions[k], walls.normals[k], walls.spacings[k], walls.layers[k], walls.areas[k]);
    const int layers = 1 + *std::max_element(walls.layers.begin(), walls.layers.end());
    if (const std::size_t left = walls.positions.size() - within.positions.size(); left > 0) {
        within.filledThrough = outside == 0;
        within.notes.push_back(outside == 0
                                   ? fmt::format("the layers from its faces meet inside it, where it is thinner than twice its {} layers ({} "
                                                 "wall particles on another layer's place left out)",
                                                 layers, left)
                                   : fmt::format("thinner than its {} layers: {} wall particles that would lie outside it left out and {} on another "
                                                 "layer's; it holds {} behind each face, and the fluid on its sides reach each other through it",
                                                 layers, outside, left - outside, 1 + *std::max_element(within.layers.begin(), within.layers.end())));
    }
    walls = std::move(within);
}

// A polyline (open) or polygon (closed) patch: its points and side, laid by addWallPath.
template <bool Closed>
WallPatchParticles<2> wallPathPatch(const Dictionary& patch, double dx, int layers, double offset) {
    const std::vector<Vec<2>> points = patch.getVectorList<2>("points");
    if (points.size() < (Closed ? 3u : 2u)) patch.fail("points", Closed ? "a polygon needs at least 3 points" : "a polyline needs at least 2 points");
    WallPatchParticles<2> walls;
    const double sign = sideSign(patch);
    addWallPath(patch, points, Closed, sign, dx, layers, offset, walls);
    // A polygon whose fluid side is its outside is a solid body the fluid regions leave out, as
    // a circle with `fluidInside no` is (left of a counter-clockwise loop is its inside).
    if (Closed && sign * signedArea(points) < 0.0) {
        walls.solid = [points](const Vec<2>& x) { return insideLoop(points, x); };
        keepWithinSolid(walls, dx);
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
    for (int k = 1; k <= fine; ++k)
        arc[k] = arc[k - 1] + (point(2 * std::numbers::pi * k / fine) - point(2 * std::numbers::pi * (k - 1) / fine)).norm();
    const double perimeter = arc.back();
    WallPatchParticles<2> walls;
    for (int layer = 0; layer < layers; ++layer) {
        const double distance = (layer + offset) * dx;
        if (!fluidInside && distance >= axes.minCoeff()) break;  // past the middle of the solid
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
    if (!fluidInside) {
        walls.solid = [centre, axes](const Vec<2>& x) {
            return std::pow((x.x() - centre.x()) / axes.x(), 2) + std::pow((x.y() - centre.y()) / axes.y(), 2) < 1.0;
        };
        keepWithinSolid(walls, dx);
    }
    return walls;
}

}  // namespace

WallLayout wallLayout(const Dictionary& patch, const std::function<WallLayout()>& fromModel,
                      const std::function<std::optional<double>()>& offsetOfModel) {
    if (!patch.found("layers")) {
        WallLayout layout = fromModel();
        if (patch.found("firstLayerOffset")) layout.firstLayerOffset = patch.getNonNegative("firstLayerOffset");
        return layout;
    }
    const int layers = patch.get<int>("layers");
    // A kernel support needs a few layers; thousands would be a slip that fills the memory.
    constexpr int maxLayers = 1000;
    if (layers < 1 || layers > maxLayers) patch.fail("layers", fmt::format("must be from 1 to {}, found {}", maxLayers, layers));
    if (patch.found("firstLayerOffset")) return {layers, patch.getNonNegative("firstLayerOffset")};
    const std::optional<double> modelOffset = offsetOfModel ? offsetOfModel() : std::nullopt;
    return {layers, modelOffset.value_or(0.5)};
}

namespace {

// The keywords every wall patch takes, after its own.
std::vector<CoefficientDoc> withLayout(std::vector<CoefficientDoc> own) {
    own.push_back({"layers", "model", "layers of wall particles; left out: what the patch's model in constant/boundaryProperties needs"});
    own.push_back(
        {"firstLayerOffset", "model",
         "the first layer's distance behind the wall [dx] (0: on it); left out: the patch's model's, 0 for a wall-force model, 0.5 otherwise"});
    return own;
}

// A 2D-only shape's generation, as a registry factory.
template <int D>
auto planar(WallPatchParticles<2> (*generate)(const Dictionary&, double, int, double)) {
    return [generate](const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>&) -> WallPatchParticles<D> {
        if constexpr (D == 2)
            return generate(patch, dx, layout.layers, layout.firstLayerOffset);
        else
            shapeForOtherDimensions(patch, "wall patch", "2D", D);
    };
}

}  // namespace

template <int D>
WallPatchRegistry<D> makeWallPatchRegistry() {
    WallPatchRegistry<D> registry("wall patch type");
    registry.add(
        "boxWalls",
        {"the shell around a box, the lattice continued outwards, corners included; any extent (the last spacing along a face adjusted); 1D-3D", "",
         withLayout({{"min", "", "lower corner"}, {"max", "", "upper corner"}, {"open", "()", "faces left open: (xMin xMax yMin yMax zMin zMax)"}})},
        [](const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>&) {
            return boxWalls<D>(patch, dx, layout.layers, layout.firstLayerOffset);
        });
    registry.add("box",
                 {"a solid obstacle: its lattice `layers` deep from each face, normals out of the nearest face; 1D-3D", "",
                  withLayout({{"min", "", "lower corner"}, {"max", "", "upper corner"}})},
                 [](const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>&) {
                     return boxObstacle<D>(patch, dx, layout.layers, layout.firstLayerOffset);
                 });
    registry.add(
        "polyline",
        {"an open path of straight faces, particles at their spacings' centres, corners filled behind a convex turn; 2D", "",
         withLayout({{"points", "", "((x y) ...), at least 2"}, {"side", "left", "the fluid's side of the direction of travel: left or right"}})},
        planar<D>(wallPathPatch<false>));
    registry.add(
        "polygon",
        {"a closed path of straight faces, a particle on every vertex (bisector normal); with the fluid outside, a solid body the fluid regions "
         "leave "
         "out; 2D",
         "", withLayout({{"points", "", "((x y) ...), at least 3"}, {"side", "left", "the fluid's side of the direction of travel: left or right"}})},
        planar<D>(wallPathPatch<true>));
    const std::vector<CoefficientDoc> fluidInside{{"fluidInside", "", "yes: a tank; no: a solid body the fluid regions leave out"}};
    registry.add("circle", {"a circle at equal arc steps; 2D", "", withLayout({{"centre", "", "(x y)"}, {"radius", "", "[m]"}, fluidInside[0]})},
                 planar<D>(ellipse));
    registry.add("ellipse",
                 {"an ellipse at equal arc steps; 2D", "", withLayout({{"centre", "", "(x y)"}, {"semiAxes", "", "(a b) [m]"}, fluidInside[0]})},
                 planar<D>(ellipse));
    registry.add("surface",
                 {"a closed surface from a file (3D: STL or OBJ; 2D: OBJ polylines or a surface cut at z = slice): one layer sampled on it, more the "
                  "lattice behind it; 2D, 3D",
                  "",
                  withLayout({{"file", "", "STL or OBJ, relative to the case"},
                              {"scale", "1", "multiplies the file's coordinates"},
                              {"slice", "0", "2D: z of the cut through a surface"},
                              fluidInside[0]})},
                 [](const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>& domain) -> WallPatchParticles<D> {
                     if constexpr (D >= 2)
                         return surfaceWalls<D>(patch, dx, layout, domain.caseDirectory, domain.min, domain.max);
                     else
                         shapeForOtherDimensions(patch, "wall patch", "2D and 3D", D);
                 });
    return registry;
}

template <int D>
WallPatchParticles<D> generateWallPatch(const Dictionary& patch, double dx, const WallLayout& layout, const GenerationDomain<D>& domain) {
    return selectByType(makeWallPatchRegistry<D>(), patch, patch, dx, layout, domain);
}

template WallPatchRegistry<1> makeWallPatchRegistry<1>();
template WallPatchRegistry<2> makeWallPatchRegistry<2>();
template WallPatchRegistry<3> makeWallPatchRegistry<3>();
template WallPatchParticles<1> generateWallPatch<1>(const Dictionary&, double, const WallLayout&, const GenerationDomain<1>&);
template WallPatchParticles<2> generateWallPatch<2>(const Dictionary&, double, const WallLayout&, const GenerationDomain<2>&);
template WallPatchParticles<3> generateWallPatch<3>(const Dictionary&, double, const WallLayout&, const GenerationDomain<3>&);

}  // namespace sph
