// Wall patch generation: the box obstacle's particles, layers, normals and solid inside.
#include "generation/WallPatches.hpp"

#include "generation/CubeSurface.hpp"

#include <fmt/format.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <optional>
#include <type_traits>

using namespace sph;

// A domain around every patch here.
template <int D>
const GenerationDomain<D> anywhere{Vec<D>::Constant(-10.0), Vec<D>::Constant(10.0), ""};

// A patch that names its layers: its wall model is never asked.
template <int D>
WallPatchParticles<D> generateWithItsLayers(const Dictionary& patch, double dx, const GenerationDomain<D>& domain) {
    const WallLayout layout = wallLayout(patch, []() -> WallLayout { throw std::logic_error("the model's layout was asked for"); });
    return generateWallPatch<D>(patch, dx, layout, domain);
}

TEST(WallPatches, BoxObstacleIsItsLatticeLayersDeepWithNormalsOutOfTheNearestFace) {
    // A 10 x 6 dx block, 2 layers: everything but the 6 x 2 core (hand count 60 - 12 = 48).
    const double dx = 0.1;
    const Dictionary patch = Dictionary::fromString("type box; min (1 0); max (2 0.6); layers 2;", "block");
    const WallPatchParticles<2> walls = generateWithItsLayers<2>(patch, dx, anywhere<2>);
    ASSERT_EQ(walls.positions.size(), 48u);
    int surface = 0;
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const Vec<2>& x = walls.positions[k];
        EXPECT_GT(x.x(), 1.0);
        EXPECT_LT(x.x(), 2.0);
        EXPECT_NEAR(walls.normals[k].norm(), 1.0, 1e-14);
        EXPECT_DOUBLE_EQ(walls.spacings[k], dx);
        const double depth = std::min({x.x() - 1.0, 2.0 - x.x(), x.y(), 0.6 - x.y()});
        EXPECT_EQ(walls.layers[k], static_cast<int>(std::lround(depth / dx - 0.5)));
        if (walls.layers[k] == 0) ++surface;
    }
    EXPECT_EQ(surface, 28);  // the perimeter ring of a 10 x 6 lattice
    // Hand-picked: the corner particle's normal is diagonal, a left-face particle's points -x.
    int checked = 0;
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        if ((walls.positions[k] - Vec<2>(1.05, 0.05)).norm() < 1e-9) {
            EXPECT_LT((walls.normals[k] - Vec<2>(-1, -1).normalized()).norm(), 1e-14);
            ++checked;
        }
        if ((walls.positions[k] - Vec<2>(1.05, 0.35)).norm() < 1e-9) {
            EXPECT_LT((walls.normals[k] - Vec<2>(-1, 0)).norm(), 1e-14);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 2);
    ASSERT_TRUE(walls.solid);
    EXPECT_TRUE(walls.solid(Vec<2>(1.5, 0.3)));
    EXPECT_FALSE(walls.solid(Vec<2>(0.95, 0.3)));
}

TEST(WallPatches, BoxUnderHalfASpacingIsRefused) {
    const Dictionary patch = Dictionary::fromString("type box; min (1 0 0); max (2 0.04 1); layers 1;", "block");
    try {
        generateWithItsLayers<3>(patch, 0.1, anywhere<3>);
        FAIL() << "a box 0.4 dx thick was accepted";
    } catch (const FatalError& error) {
        EXPECT_NE(std::string(error.what()).find("must be at least half a spacing dx = 0.1 (it is 0.4 dx)"), std::string::npos) << error.what();
    }
}

TEST(WallPatches, BoxWallsOfAnyLengthAdjustTheLastSpacingAndKeepTheLayersAtTheirDistances) {
    // A 1.03 x 0.6 tank at dx = 0.1 (10.3 dx): 10 floor particles, the last dx/2 inside x = 1.03,
    // 0.8 dx after the one before (the last spacing 1.3 dx less the half spacing each end keeps
    // is hand-computed: 1.03 - 0.05 - 0.85 = 0.13). The right wall's layers lie 0.05 and 0.15
    // beyond x = 1.03, as the left wall's lie before x = 0.
    const double dx = 0.1;
    const Dictionary patch = Dictionary::fromString("type boxWalls; min (0 0); max (1.03 0.6); layers 2; open (yMax);", "tank");
    const WallPatchParticles<2> walls = generateWithItsLayers<2>(patch, dx, anywhere<2>);
    std::vector<double> floor, rightWall;
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const Vec<2>& x = walls.positions[k];
        if (std::abs(x.y() + 0.05) < 1e-12 && x.x() > 0.0 && x.x() < 1.03) floor.push_back(x.x());
        if (std::abs(x.y() - 0.35) < 1e-12 && x.x() > 1.03) rightWall.push_back(x.x());
    }
    std::sort(floor.begin(), floor.end());
    ASSERT_EQ(floor.size(), 10u);
    EXPECT_NEAR(floor[8], 0.85, 1e-12);
    EXPECT_NEAR(floor[9], 0.98, 1e-12);
    ASSERT_EQ(rightWall.size(), 2u);
    EXPECT_NEAR(std::min(rightWall[0], rightWall[1]), 1.08, 1e-12);
    EXPECT_NEAR(std::max(rightWall[0], rightWall[1]), 1.18, 1e-12);
    ASSERT_EQ(walls.notes.size(), 1u);
    EXPECT_EQ(walls.notes[0], "the x extent 1.03 is 10.3 dx: the last spacing is 1.3 dx");
}

TEST(WallPatches, OneLayerBoxWallsOfAnyLengthStillTileTheirFaces) {
    // 1.03 x 0.57 x 0.4 at dx = 0.1: the face particles' area vectors still add up to each face.
    const double dx = 0.1;
    const Dictionary patch =
        Dictionary::fromString("type boxWalls; min (0 0 0); max (1.03 0.57 0.4); layers 1; firstLayerOffset 0; open (zMax);", "tank");
    const WallPatchParticles<3> walls = generateWithItsLayers<3>(patch, dx, anywhere<3>);
    Vec<3> floorArea = Vec<3>::Zero();
    double sideX = 0.0, sideY = 0.0;
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const Vec<3>& x = walls.positions[k];
        const Vec<3> areaVector = walls.areas[k] * walls.normals[k];
        if (std::abs(x.z()) < 1e-12) floorArea += areaVector;
        if (std::abs(x.x() - 1.03) < 1e-12) sideX += areaVector.x();
        if (std::abs(x.y()) < 1e-12) sideY += areaVector.y();
    }
    EXPECT_NEAR(floorArea.z(), 1.03 * 0.57, 1e-12);
    EXPECT_NEAR(sideX, -0.57 * 0.4, 1e-12);
    EXPECT_NEAR(sideY, 1.03 * 0.4, 1e-12);
}

TEST(WallPatches, OneLayerBoxWallsOnTheSurfaceTileTheFacesWithCornersOnTheCorners) {
    // A 1 x 0.6 x 0.4 tank at dx = 0.1, open at the top, one layer on the wall (offset 0). The
    // face particles stand for dx^2 each and tile the faces; edge and corner particles sit on
    // the box's edges and corners and stand for nothing, so the area vectors sum to the faces.
    const double dx = 0.1;
    const Dictionary patch =
        Dictionary::fromString("type boxWalls; min (0 0 0); max (1 0.6 0.4); layers 1; firstLayerOffset 0; open (zMax);", "tank");
    const WallPatchParticles<3> walls = generateWithItsLayers<3>(patch, dx, anywhere<3>);
    Vec<3> upward = Vec<3>::Zero();  // the z-area of the floor
    double sideX = 0.0;              // the x-area of the xMin side
    int corners = 0;
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const Vec<3>& x = walls.positions[k];
        // On the box's surface: on at least one face, inside the box's extent on the others.
        const double toFace = std::min({std::abs(x.x()), std::abs(x.x() - 1.0), std::abs(x.y()), std::abs(x.y() - 0.6), std::abs(x.z())});
        EXPECT_LT(toFace, 1e-12) << x.transpose();
        EXPECT_GE(x.x(), -1e-12);
        EXPECT_LE(x.x(), 1.0 + 1e-12);
        const Vec<3> areaVector = walls.areas[k] * walls.normals[k];
        if (std::abs(x.z()) < 1e-12) upward += areaVector;
        if (std::abs(x.x()) < 1e-12) sideX += areaVector.x();
        if (walls.areas[k] == 0.0) ++corners;
    }
    EXPECT_NEAR(upward.z(), 1.0 * 0.6, 1e-12);
    EXPECT_NEAR(sideX, 0.6 * 0.4, 1e-12);
    // Edges and corners: the floor's 4 edges (10 + 10 + 6 + 6) + 4 corners, the 4 vertical edges of 4 particles each.
    EXPECT_EQ(corners, 2 * 10 + 2 * 6 + 4 + 4 * 4);
}

TEST(WallPatches, PolygonVertexStandsForHalfOfEachSide) {
    // A 1 x 1 square at dx = 0.25: at each vertex the two half-sides' area vectors add to
    // (dx/2)(n1 + n2), of length dx/sqrt(2), along the bisector.
    const Dictionary patch = Dictionary::fromString("type polygon; points ((0 0) (1 0) (1 1) (0 1)); layers 1; firstLayerOffset 0;", "tank");
    const WallPatchParticles<2> walls = generateWithItsLayers<2>(patch, 0.25, anywhere<2>);
    ASSERT_EQ(walls.positions.size(), 16u);
    Vec<2> total = Vec<2>::Zero();
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const bool vertex = (walls.positions[k] - Vec<2>(0, 0)).norm() < 1e-12 || (walls.positions[k] - Vec<2>(1, 1)).norm() < 1e-12;
        if (vertex) {
            EXPECT_NEAR(walls.areas[k], 0.25 / std::sqrt(2.0), 1e-15);
        } else if ((walls.positions[k] - Vec<2>(0.5, 0)).norm() < 1e-12) {
            EXPECT_DOUBLE_EQ(walls.areas[k], 0.25);
        }
        total += walls.areas[k] * walls.normals[k];
    }
    EXPECT_LT(total.norm(), 1e-14);  // a closed surface
}

TEST(WallPatches, PolygonWithTheFluidOutsideIsASolidBody) {
    // A triangle, counter-clockwise: its left is its inside. With `side right` (or clockwise with
    // `side left`) the fluid is outside and the fluid regions leave out the triangle's inside;
    // with the fluid inside it is a tank, and nothing is a solid.
    const auto generated = [](const char* points, const char* side) {
        return generateWithItsLayers<2>(
            Dictionary::fromString(fmt::format("type polygon; points ({}); side {}; layers 1; firstLayerOffset 0;", points, side), "body"), 0.1,
            anywhere<2>);
    };
    const char* counterClockwise = "(0 0) (1 0) (0.5 0.8)";
    const char* clockwise = "(0 0) (0.5 0.8) (1 0)";
    for (const WallPatchParticles<2>& body : {generated(counterClockwise, "right"), generated(clockwise, "left")}) {
        ASSERT_TRUE(body.solid);
        EXPECT_TRUE(body.solid(Vec<2>(0.5, 0.3)));
        EXPECT_FALSE(body.solid(Vec<2>(0.5, 0.9)));
        EXPECT_FALSE(body.solid(Vec<2>(0.1, 0.5)));  // beside a slanted side, level with the inside
    }
    EXPECT_FALSE(generated(counterClockwise, "left").solid);
    EXPECT_FALSE(generated(clockwise, "right").solid);
}

namespace {

// The smallest distance between two particles of a patch.
double closestPair(const WallPatchParticles<2>& walls) {
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < walls.positions.size(); ++i)
        for (std::size_t j = i + 1; j < walls.positions.size(); ++j) closest = std::min(closest, (walls.positions[i] - walls.positions[j]).norm());
    return closest;
}

// How many particles of a patch sit on the lattice point (i + 1/2, j + 1/2) dx, and in which layer.
int countAt(const WallPatchParticles<2>& walls, double dx, double i, double j, int layer) {
    int found = 0;
    for (std::size_t k = 0; k < walls.positions.size(); ++k)
        if ((walls.positions[k] - dx * Vec<2>(i + 0.5, j + 0.5)).norm() < 1e-12 && walls.layers[k] == layer) ++found;
    return found;
}

}  // namespace

TEST(WallPatches, SolidThinnerThanItsLayersKeepsThemInside) {
    // A plate 2 dx thick and 10 dx tall with three layers from each face (dummy particles'): the
    // third layers fell dx/2 outside the far faces, among the fluid, and the second layers on the
    // other face's first. Now every particle is inside and none two within dx/4 (the closest pair
    // of a corner, dx/2, kept). A circle of radius 1.2 dx: no layer laid past its middle.
    const double dx = 0.01;
    const WallPatchParticles<2> plate = generateWithItsLayers<2>(
        Dictionary::fromString("type polygon; points ((0.49 0) (0.51 0) (0.51 0.1) (0.49 0.1)); side right; layers 3;", "baffle"), dx, anywhere<2>);
    ASSERT_TRUE(plate.solid);
    for (const Vec<2>& x : plate.positions) EXPECT_TRUE(x.x() > 0.49 && x.x() < 0.51 && x.y() > 0.0 && x.y() < 0.1) << x.transpose();
    EXPECT_GE(closestPair(plate), 0.25 * dx);
    ASSERT_EQ(plate.notes.size(), 1u);
    EXPECT_NE(plate.notes[0].find("thinner than its 3 layers"), std::string::npos) << plate.notes[0];
    const WallPatchParticles<2> thick = generateWithItsLayers<2>(
        Dictionary::fromString("type polygon; points ((0.4 0) (0.6 0) (0.6 0.1) (0.4 0.1)); side right; layers 3;", "block"), dx, anywhere<2>);
    EXPECT_TRUE(thick.notes.empty());
    EXPECT_EQ(*std::max_element(thick.layers.begin(), thick.layers.end()), 2);
    const WallPatchParticles<2> pin = generateWithItsLayers<2>(
        Dictionary::fromString("type circle; centre (0 0); radius 0.012; fluidInside no; layers 3;", "pin"), dx, anywhere<2>);
    for (const Vec<2>& x : pin.positions) EXPECT_LT(x.norm(), 0.012) << x.transpose();
    EXPECT_GE(closestPair(pin), 0.25 * dx);
}

TEST(WallPatches, LayeredPolylineFillsTheBlockBehindATanksCorner) {
    // An L-shaped tank corner, fluid above and right of it, dx = 0.1, 3 layers from dx/2: each
    // side's 10 x 3 particles and the 3 x 3 block behind the corner, each particle in the layer
    // of its larger distance from the two faces (hand count 69; before, the block was empty).
    const double dx = 0.1;
    const Dictionary patch = Dictionary::fromString("type polyline; points ((0 1) (0 0) (1 0)); layers 3;", "tank");
    const WallPatchParticles<2> walls = generateWithItsLayers<2>(patch, dx, anywhere<2>);
    ASSERT_EQ(walls.positions.size(), 69u);
    EXPECT_NEAR(closestPair(walls), dx, 1e-12);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_EQ(countAt(walls, dx, -1 - i, -1 - j, std::max(i, j)), 1) << i << " " << j;
    const auto diagonal =
        std::find_if(walls.positions.begin(), walls.positions.end(), [&](const Vec<2>& x) { return (x - Vec<2>(-0.25, -0.25)).norm() < 1e-12; });
    ASSERT_NE(diagonal, walls.positions.end());
    EXPECT_LT((walls.normals[static_cast<std::size_t>(diagonal - walls.positions.begin())] - Vec<2>(1, 1).normalized()).norm(), 1e-12);
}

TEST(WallPatches, LayeredPolylineKeepsOneParticleWhereTheLayersOfAnInnerCornerOverlap) {
    // The same corner with the wall on its inside (side right): the two sides' layers cover the
    // same 3 x 3 block; each lattice point is kept once, hand count 30 + 30 - 9 = 51.
    const double dx = 0.1;
    const Dictionary patch = Dictionary::fromString("type polyline; points ((0 1) (0 0) (1 0)); layers 3; side right;", "wedge");
    const WallPatchParticles<2> walls = generateWithItsLayers<2>(patch, dx, anywhere<2>);
    ASSERT_EQ(walls.positions.size(), 51u);
    EXPECT_NEAR(closestPair(walls), dx, 1e-12);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_EQ(countAt(walls, dx, i, j, std::min(i, j)), 1) << i << " " << j;
}

TEST(WallPatches, LayeredPolylineTankIsTheBoxWallsTank) {
    // hydrostaticTank2D's tank written as a polyline gives boxWalls' particles, corners included
    // (832; before, 800: its still water lost 26 particles through the corners by t = 2 and its
    // hydrostatic pressure error was 8.7 % against boxWalls' 0.73 %).
    const double dx = 0.02;
    const WallPatchParticles<2> path =
        generateWithItsLayers<2>(Dictionary::fromString("type polyline; points ((0 1) (0 0) (2 0) (2 1)); layers 4;", "tank"), dx, anywhere<2>);
    const WallPatchParticles<2> box =
        generateWithItsLayers<2>(Dictionary::fromString("type boxWalls; min (0 0); max (2 1); layers 4; open (yMax);", "tank"), dx, anywhere<2>);
    ASSERT_EQ(path.positions.size(), 832u);
    ASSERT_EQ(box.positions.size(), 832u);
    for (std::size_t k = 0; k < path.positions.size(); ++k) {
        const auto same =
            std::find_if(box.positions.begin(), box.positions.end(), [&](const Vec<2>& x) { return (x - path.positions[k]).norm() < 1e-12; });
        ASSERT_NE(same, box.positions.end()) << path.positions[k].transpose();
        const auto j = static_cast<std::size_t>(same - box.positions.begin());
        EXPECT_EQ(path.layers[k], box.layers[j]) << path.positions[k].transpose();
        EXPECT_LT((path.normals[k] - box.normals[j]).norm(), 1e-12) << path.positions[k].transpose();
    }
}

TEST(WallPatches, LayeredPolylineCornerOfAnyAngleHasNoGapAndNoCrowd) {
    // Bends of 45, 90, 135 and 170 degrees, 4 layers from dx/2, the wall on either side: no two
    // particles closer than dx/2; none farther from the wall than the last layer (3.5 dx), or
    // than its mitre where the wall's side is convex and the bend at most a right angle; and
    // no hole a fluid particle could pass: every point between 0.5 and 3.5 dx behind the wall
    // within dx of a particle (a lattice: 0.71 dx; measured at most 0.95 dx, where the 135-degree
    // bend's overlapping layers meet and where a 45-degree fill rounds 1.4 dx to one spacing).
    const double dx = 0.05;
    const Vec<2> start(0, 0), corner(1, 0);
    for (const double degrees : {45.0, 90.0, 135.0, 170.0}) {
        const double turn = degrees * std::numbers::pi / 180.0;
        const Vec<2> end = corner + Vec<2>(std::cos(turn), std::sin(turn));
        for (const double sign : {1.0, -1.0}) {
            const std::string label = fmt::format("{} degrees, side {}", degrees, sign > 0 ? "left" : "right");
            const Dictionary patch = Dictionary::fromString(fmt::format("type polyline; points ((0 0) (1 0) ({:.17g} {:.17g})); layers 4; side {};",
                                                                        end.x(), end.y(), sign > 0 ? "left" : "right"),
                                                            "bend");
            const WallPatchParticles<2> walls = generateWithItsLayers<2>(patch, dx, anywhere<2>);
            EXPECT_GT(closestPair(walls), 0.5 * dx) << label;
            // Distance to the path, and whether x is on the wall's side (behind the nearer face;
            // nearest to the corner itself: the wall's side when the path turns towards the fluid).
            const auto behindWall = [&](const Vec<2>& x, double& distance) {
                const std::array<std::pair<Vec<2>, Vec<2>>, 2> faces{{{start, corner}, {corner, end}}};
                bool behind = false;
                distance = std::numeric_limits<double>::infinity();
                for (const auto& [a, b] : faces) {
                    const Vec<2> along = b - a, normal = sign * Vec<2>(-along.y(), along.x()).normalized();
                    const double t = std::clamp((x - a).dot(along) / along.squaredNorm(), 0.0, 1.0);
                    const double d = (x - (a + t * along)).norm();
                    if (d < distance) {
                        distance = d;
                        const bool atCorner = (a + t * along - corner).norm() < 1e-12;
                        behind = atCorner ? sign * turn > 0.0 : (x - a).dot(normal) < 0.0;
                    }
                }
                return behind;
            };
            double distance = 0.0, farthest = 0.0, largestHole = 0.0;
            for (const Vec<2>& p : walls.positions) {
                EXPECT_TRUE(behindWall(p, distance)) << label << ": " << p.transpose();
                farthest = std::max(farthest, distance);
            }
            const bool mitre = sign > 0.0 && degrees <= 90.0;
            EXPECT_LT(farthest, 3.5 * dx / (mitre ? std::cos(0.5 * turn) : 1.0) + 1e-12) << label;
            for (double x = 0.7; x < 1.3; x += 0.05 * dx)
                for (double y = -0.3; y < 0.3; y += 0.05 * dx) {
                    if (!behindWall(Vec<2>(x, y), distance) || distance < 0.5 * dx || distance > 3.5 * dx) continue;
                    double nearest = std::numeric_limits<double>::infinity();
                    for (const Vec<2>& p : walls.positions) nearest = std::min(nearest, (p - Vec<2>(x, y)).norm());
                    largestHole = std::max(largestHole, nearest);
                }
            EXPECT_LT(largestHole, dx) << label;
        }
    }
}

TEST(WallPatches, SurfaceIn2DOfOneLayerIsAPolygonsWallAndOfTwoTheLatticeBehindIt) {
    // The unit square at dx = 0.1 (an OBJ polyline, written clockwise): one layer on it is the
    // polygon's wall, particle for particle; two layers are the lattice outside it less than
    // 0.2 away: 4 x 10 x 2 beside the sides and 3 at each corner ((0.15, 0.15) is 0.212 away).
    const double dx = 0.1;
    const std::vector<Vec<2>> clockwise{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    const std::filesystem::path file = writeCurveObj("tankSquare.obj", clockwise);
    const GenerationDomain<2> domain{Vec<2>::Constant(-0.5), Vec<2>::Constant(1.5), ""};
    const WallPatchParticles<2> sampled = generateWithItsLayers<2>(
        Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 1; firstLayerOffset 0; fluidInside yes;", file.string()), "tank"), dx,
        domain);
    const WallPatchParticles<2> polygon = generateWithItsLayers<2>(
        Dictionary::fromString("type polygon; points ((0 0) (1 0) (1 1) (0 1)); layers 1; firstLayerOffset 0;", "tank"), dx, domain);
    ASSERT_EQ(sampled.positions.size(), 40u);
    ASSERT_EQ(polygon.positions.size(), 40u);
    for (std::size_t k = 0; k < sampled.positions.size(); ++k) {
        const auto same = std::find_if(polygon.positions.begin(), polygon.positions.end(),
                                       [&](const Vec<2>& x) { return (x - sampled.positions[k]).norm() < 1e-12; });
        ASSERT_NE(same, polygon.positions.end()) << sampled.positions[k].transpose();
        const auto j = static_cast<std::size_t>(same - polygon.positions.begin());
        EXPECT_LT((sampled.normals[k] - polygon.normals[j]).norm(), 1e-12);
        EXPECT_NEAR(sampled.areas[k], polygon.areas[j], 1e-15);
    }
    const WallPatchParticles<2> layered = generateWithItsLayers<2>(
        Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 2; fluidInside yes;", file.string()), "tank"), dx, domain);
    EXPECT_EQ(layered.positions.size(), 4u * 10 * 2 + 4 * 3);
    // fluidInside no: a body; its lattice inside, 2 deep from each side, 10^2 - 6^2.
    const WallPatchParticles<2> body = generateWithItsLayers<2>(
        Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 2; fluidInside no;", file.string()), "body"), dx, domain);
    EXPECT_EQ(body.positions.size(), 64u);
    ASSERT_TRUE(body.solid);
    EXPECT_TRUE(body.solid(Vec<2>(0.5, 0.5)));
}

TEST(WallPatches, SurfaceIn2DResamplesAFinelyTessellatedCurveAtTheSpacing) {
    // A circle of radius 1 as a 400-gon (turns of 0.9 degrees: no corner): one layer is resampled
    // at equal lengths, lround(perimeter / dx) = 63 particles at dx = 0.1, each on the curve,
    // normals towards the centre, lengths adding up to the resampled polygon's perimeter, area vectors to zero.
    std::vector<Vec<2>> circle;
    for (int k = 0; k < 400; ++k) circle.emplace_back(std::cos(2 * std::numbers::pi * k / 400), std::sin(2 * std::numbers::pi * k / 400));
    const std::filesystem::path file = writeCurveObj("circle.obj", circle);
    const WallPatchParticles<2> walls = generateWithItsLayers<2>(
        Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 1; firstLayerOffset 0; fluidInside yes;", file.string()), "tank"), 0.1,
        {Vec<2>::Constant(-2), Vec<2>::Constant(2), ""});
    ASSERT_EQ(walls.positions.size(), 63u);
    const double perimeter = 400 * 2 * std::sin(std::numbers::pi / 400);
    double length = 0.0;
    Vec<2> total = Vec<2>::Zero();
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        EXPECT_NEAR(walls.positions[k].norm(), 1.0, 1e-4);  // on the 400-gon: within 1 - cos(0.45 degrees)
        EXPECT_LT((walls.normals[k] + walls.positions[k].normalized()).norm(), 0.06);
        length += walls.spacings[k];
        total += walls.areas[k] * walls.normals[k];
    }
    // The resampled 63-gon is inscribed in the unit circle: its perimeter at most the regular
    // one's, 2 * 63 sin(pi / 63), 0.04 % short of the curve's (measured 2e-5 below it).
    const double regular = 2 * 63 * std::sin(std::numbers::pi / 63);
    EXPECT_LT(length, regular);
    EXPECT_GT(length, (1.0 - 1e-4) * regular);
    EXPECT_LT(length, perimeter);
    // A vertex's area vector is along its bisector, exactly the sum of its half-sides' only
    // where they are equally long: the resampled sides differ by about 1e-7 here.
    EXPECT_LT(total.norm(), 1e-9);
}

TEST(WallPatches, SurfaceWallOfTwoLayersIsTheLatticeWithinTwoSpacingsOutsideATank) {
    // The unit cube as a tank at dx = 0.1, two layers: hand count of the lattice points outside
    // it less than 0.2 away: faces 6 x 100 x 2, edges 12 x 10 x 3 ((0.05, 0.05), (0.05, 0.15)
    // twice; (0.15, 0.15) is 0.212 away), corners 8 x 4 ((0.05, 0.05, 0.05) and three of two 0.05s).
    const std::filesystem::path file = writeCubeObj("tankCube.obj");
    const Dictionary patch = Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 2; fluidInside yes;", file.string()), "tank");
    const WallPatchParticles<3> walls = generateWithItsLayers<3>(patch, 0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""});
    ASSERT_EQ(walls.positions.size(), 6u * 100 * 2 + 12 * 10 * 3 + 8 * 4);
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const Vec<3>& x = walls.positions[k];
        if (std::abs(x.z() + 0.15) < 1e-12 && x.x() > 0.0 && x.x() < 1.0 && x.y() > 0.0 && x.y() < 1.0) {
            EXPECT_EQ(walls.layers[k], 1);
            EXPECT_LT((walls.normals[k] - Vec<3>(0, 0, 1)).norm(), 1e-12);
        }
        if (std::abs(x.x() - 1.05) < 1e-12 && x.y() > 0.0 && x.y() < 1.0 && x.z() > 0.0 && x.z() < 1.0) {
            EXPECT_EQ(walls.layers[k], 0);
            EXPECT_LT((walls.normals[k] - Vec<3>(-1, 0, 0)).norm(), 1e-12);
        }
    }
    EXPECT_FALSE(walls.solid);
    EXPECT_THROW(
        generateWithItsLayers<3>(
            Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 2; fluidInside yes; firstLayerOffset 0;", file.string()), "tank"),
            0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""}),
        FatalError);
}

TEST(WallPatches, SurfaceWallOfOneLayerIsWhereTheLatticeColumnsPierceIt) {
    // Each face of the cube takes the 10 x 10 lattice columns that pierce it (the points on a
    // face's diagonal, which both its triangles touch, counted once): 600 particles of dx^2 on
    // the surface (offset 0), their area vectors into the fluid adding up to each face.
    const std::filesystem::path file = writeCubeObj("sampledCube.obj");
    const Dictionary patch =
        Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 1; firstLayerOffset 0; fluidInside yes;", file.string()), "tank");
    const WallPatchParticles<3> walls = generateWithItsLayers<3>(patch, 0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""});
    ASSERT_EQ(walls.positions.size(), 600u);
    Vec<3> floorArea = Vec<3>::Zero(), total = Vec<3>::Zero();
    for (std::size_t k = 0; k < walls.positions.size(); ++k) {
        const Vec<3>& x = walls.positions[k];
        const double toFace = std::min({x.x(), 1.0 - x.x(), x.y(), 1.0 - x.y(), x.z(), 1.0 - x.z()});
        EXPECT_NEAR(toFace, 0.0, 1e-12);
        EXPECT_NEAR(walls.areas[k], 0.01, 1e-15);
        if (x.z() < 1e-12) floorArea += walls.areas[k] * walls.normals[k];
        total += walls.areas[k] * walls.normals[k];
    }
    EXPECT_LT((floorArea - Vec<3>(0, 0, 1)).norm(), 1e-12);
    EXPECT_LT(total.norm(), 1e-12);
    // As a solid body (fluidInside no) the normals point out and fluid regions leave out its inside.
    const Dictionary body =
        Dictionary::fromString(fmt::format("type surface; file \"{}\"; layers 1; firstLayerOffset 0; fluidInside no;", file.string()), "body");
    const WallPatchParticles<3> solid = generateWithItsLayers<3>(body, 0.1, {Vec<3>::Constant(-0.5), Vec<3>::Constant(1.5), ""});
    ASSERT_TRUE(solid.solid);
    EXPECT_TRUE(solid.solid(Vec<3>(0.5, 0.5, 0.5)));
    EXPECT_FALSE(solid.solid(Vec<3>(1.2, 0.5, 0.5)));
    for (std::size_t k = 0; k < solid.positions.size(); ++k)
        if (solid.positions[k].z() < 1e-12) {
            EXPECT_LT((solid.normals[k] - Vec<3>(0, 0, -1)).norm(), 1e-12);
        }
}

TEST(WallPatches, APatchWithoutLayersTakesItsModelsLayoutAndItsOwnOffset) {
    const auto fromModel = [] { return WallLayout{4, 0.5}; };
    const WallLayout own = wallLayout(Dictionary::fromString("type boxWalls; min (0 0); max (1 1); layers 2;", "tank"), fromModel);
    EXPECT_EQ(own.layers, 2);
    EXPECT_EQ(own.firstLayerOffset, 0.5);
    const WallLayout model = wallLayout(Dictionary::fromString("type boxWalls; min (0 0); max (1 1);", "tank"), fromModel);
    EXPECT_EQ(model.layers, 4);
    EXPECT_EQ(model.firstLayerOffset, 0.5);
    const WallLayout offset = wallLayout(Dictionary::fromString("type boxWalls; min (0 0); max (1 1); firstLayerOffset 0.25;", "tank"), fromModel);
    EXPECT_EQ(offset.layers, 4);
    EXPECT_EQ(offset.firstLayerOffset, 0.25);
}

TEST(WallPatches, APatchWithLayersButNoOffsetTakesItsModelsOffset) {
    const auto fromModel = []() -> WallLayout { throw std::logic_error("the model's layout was asked for"); };
    const auto wallForceModel = [] { return std::optional<double>(0.0); };
    const auto noModel = [] { return std::optional<double>(); };
    const auto notAsked = []() -> std::optional<double> { throw std::logic_error("the model's offset was asked for"); };
    const Dictionary layersOnly = Dictionary::fromString("type boxWalls; min (0 0); max (1 1); layers 1;", "tank");
    EXPECT_EQ(wallLayout(layersOnly, fromModel, wallForceModel).firstLayerOffset, 0.0);
    EXPECT_EQ(wallLayout(layersOnly, fromModel, noModel).firstLayerOffset, 0.5);
    EXPECT_EQ(wallLayout(layersOnly, fromModel).firstLayerOffset, 0.5);
    const Dictionary named = Dictionary::fromString("type boxWalls; min (0 0); max (1 1); layers 1; firstLayerOffset 0.5;", "tank");
    const WallLayout own = wallLayout(named, fromModel, notAsked);
    EXPECT_EQ(own.layers, 1);
    EXPECT_EQ(own.firstLayerOffset, 0.5);
}

TEST(WallPatches, AShapeOfAnotherDimensionOrAnUnknownOneIsRefusedAtItsType) {
    const auto failure = [](const std::string& text, auto dimension) {
        constexpr int D = decltype(dimension)::value;
        try {
            generateWithItsLayers<D>(Dictionary::fromString(text, "tank"), 0.1, anywhere<D>);
        } catch (const FatalError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(failure("type polyline; points ((0 0) (1 0)); layers 1;", std::integral_constant<int, 3>{})
                  .find("wall patch type 'polyline' is for 2D cases; this case is 3D"),
              std::string::npos);
    EXPECT_NE(failure("type surface; file \"a.obj\"; layers 1; fluidInside yes;", std::integral_constant<int, 1>{})
                  .find("is for 2D and 3D cases; this case is 1D"),
              std::string::npos);
    const std::string unknown = failure("type polyLine; points ((0 0) (1 0)); layers 1;", std::integral_constant<int, 2>{});
    EXPECT_NE(unknown.find("unknown wall patch type 'polyLine'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("did you mean 'polyline'?"), std::string::npos) << unknown;
}
