// Wall patch generation: the box obstacle's particles, layers, normals and solid inside.
#include "generation/WallPatches.hpp"

#include <gtest/gtest.h>

using namespace sph;

TEST(WallPatches, BoxObstacleIsItsLatticeLayersDeepWithNormalsOutOfTheNearestFace) {
    // A 10 x 6 dx block, 2 layers: everything but the 6 x 2 core (hand count 60 - 12 = 48).
    const double dx = 0.1;
    const Dictionary patch = Dictionary::fromString("type box; min (1 0); max (2 0.6); layers 2;", "block");
    const WallPatchParticles<2> walls = generateWallPatch<2>(patch, dx);
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

TEST(WallPatches, BoxObstacleNeedsWholeSpacings) {
    const Dictionary patch = Dictionary::fromString("type box; min (1 0 0); max (2 0.65 1); layers 1;", "block");
    EXPECT_THROW(generateWallPatch<3>(patch, 0.1), FatalError);
}

TEST(WallPatches, OneLayerBoxWallsOnTheSurfaceTileTheFacesWithCornersOnTheCorners) {
    // A 1 x 0.6 x 0.4 tank at dx = 0.1, open at the top, one layer on the wall (offset 0). The
    // face particles stand for dx^2 each and tile the faces; edge and corner particles sit on
    // the box's edges and corners and stand for nothing, so the area vectors sum to the faces.
    const double dx = 0.1;
    const Dictionary patch =
        Dictionary::fromString("type boxWalls; min (0 0 0); max (1 0.6 0.4); layers 1; firstLayerOffset 0; open (zMax);", "tank");
    const WallPatchParticles<3> walls = generateWallPatch<3>(patch, dx);
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
    const WallPatchParticles<2> walls = generateWallPatch<2>(patch, 0.25);
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
