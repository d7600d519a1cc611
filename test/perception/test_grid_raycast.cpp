#include <gtest/gtest.h>

#include "ari_social_sim/perception/grid_raycast.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

using test::map_with_wall;

TEST(GridRaycast, AWallBlocksSegmentsThatCrossIt) {
  // Wall along x = 2 from y = -1 to 1.
  const model::OccupancyGrid grid = map_with_wall({2.0, -1.0}, {2.0, 1.0});
  EXPECT_FALSE(segment_is_clear(grid, 50, {0.0, 0.0}, {4.0, 0.0}));
  EXPECT_FALSE(segment_is_clear(grid, 50, {0.0, 0.0}, {4.0, 1.5}));   // crosses at y = 0.75
  EXPECT_TRUE(segment_is_clear(grid, 50, {0.0, 0.0}, {4.0, 2.5}));    // crosses at y = 1.25
  EXPECT_TRUE(segment_is_clear(grid, 50, {0.0, 0.0}, {1.8, 0.0}));    // stops short
  EXPECT_FALSE(segment_is_clear(grid, 50, {4.0, 0.0}, {0.0, -0.5}));  // either direction
}

TEST(GridRaycast, EndCellsAndOutsideTheGridAreNotTested) {
  const model::OccupancyGrid grid = map_with_wall({2.0, -1.0}, {2.0, 1.0});
  // Starting or ending inside the wall's cells sees past them (the wall covers the two cells from
  // x = 1.95 to 2.05; 2.03 is well inside the far one).
  EXPECT_TRUE(segment_is_clear(grid, 50, {2.03, 0.0}, {5.0, 0.0}));
  EXPECT_TRUE(segment_is_clear(grid, 50, {0.0, 0.0}, {1.99, 0.0}));
  // The grid spans -10..10 m: beyond it everything is free.
  EXPECT_TRUE(segment_is_clear(grid, 50, {-30.0, 5.0}, {30.0, 5.0}));
  EXPECT_TRUE(segment_is_clear(model::OccupancyGrid{}, 50, {0.0, 0.0}, {4.0, 0.0}));
}

TEST(GridRaycast, ThresholdDecidesWhatBlocks) {
  model::OccupancyGrid grid = map_with_wall({2.0, -1.0}, {2.0, 1.0});
  EXPECT_TRUE(segment_is_clear(grid, 101, {0.0, 0.0}, {4.0, 0.0}));  // nothing reaches 101
  for (int8_t& cell : grid.cells) {
    cell = cell == model::OccupancyGrid::kOccupied ? model::OccupancyGrid::kUnknown : cell;
  }
  EXPECT_TRUE(segment_is_clear(grid, 50, {0.0, 0.0}, {4.0, 0.0}));  // unknown is free
}

TEST(GridRaycast, DiagonalWallsAreNotSlippedThrough) {
  // A diagonal wall from (1, -1) to (3, 1); rays in many directions through its middle.
  const model::OccupancyGrid grid = map_with_wall({1.0, -1.0}, {3.0, 1.0});
  for (int i = -8; i <= 8; ++i) {
    const Eigen::Vector2d target(4.0, 0.25 * i);
    // The segment t * target from the origin meets the wall's line x - y = 2 at this t.
    const double t = 2.0 / (target.x() - target.y());
    const Eigen::Vector2d crossing = t * target;
    const bool crosses_wall = t < 1.0 && crossing.x() > 1.05 && crossing.x() < 2.95;
    if (crosses_wall) {
      EXPECT_FALSE(segment_is_clear(grid, 50, {0.0, 0.0}, target)) << "target y " << target.y();
    }
  }
}

}  // namespace
}  // namespace ari_social_sim::perception
