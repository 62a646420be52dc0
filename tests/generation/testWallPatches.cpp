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
