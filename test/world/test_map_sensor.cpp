#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

TEST(MapSensor, RasterisesWallsAndFurnitureButNotAgents) {
  model::WorldDescription world = test::square_room(6.0);
  model::StaticObject table;
  table.id = 50;
  table.type = model::ShapeType::kCircle;
  table.pose.position = {4.0, 4.0};
  table.radius_m = 0.5;
  world.objects.push_back(table);
  const model::OccupancyGrid grid = rasterize_static_map(world, 0.05);
  // Floor 6.4 m at 0.05 m: 128 x 128 cells from (-0.2, -0.2).
  EXPECT_EQ(grid.width, 128);
  EXPECT_EQ(grid.height, 128);
  auto occupied = [&](double x, double y) {
    int cx, cy;
    EXPECT_TRUE(grid.cell_of({x, y}, cx, cy));
    return grid.at(cx, cy) == model::OccupancyGrid::kOccupied;
  };
  EXPECT_TRUE(occupied(3.0, 0.0));    // south wall centre line
  EXPECT_TRUE(occupied(0.02, 3.0));   // inside the 0.1 m west wall
  EXPECT_FALSE(occupied(0.08, 3.0));  // just off its inner face (x = 0.05)
  EXPECT_TRUE(occupied(4.0, 4.0));    // table centre
  EXPECT_TRUE(occupied(4.45, 4.0));   // inside its rim
  EXPECT_FALSE(occupied(4.6, 4.0));   // outside
  EXPECT_FALSE(occupied(3.0, 3.0));   // open floor
  // A wall 0.1 m thick covers 2 rows of cells along its 6.1 m: about 2 x 122 cells each.
  const size_t wall_and_table_cells = grid.occupied_count();
  EXPECT_GT(wall_and_table_cells, 4 * 2 * 118u);
  EXPECT_LT(wall_and_table_cells, 4 * 3 * 124u + 500u);

  // ARI's sensor sees the same map, with humans and ARI on the floor left out.
  Simulation simulation(world, SimulationConfig{0.05, 1, 0.05});
  HumanSpec human;
  human.id = 10;
  human.pose.position = {2.0, 2.0};
  simulation.add_human(human);
  AriSpec ari;
  ari.pose.position = {3.0, 1.5};
  simulation.add_ari(ari);
  simulation.step();
  const MapSensor& sensor = simulation.ari()->map_sensor();
  ASSERT_TRUE(sensor.has_map());
  EXPECT_EQ(sensor.map().cells, grid.cells);
}

TEST(MapSensor, GridsBeyondTheCellLimitAreRefusedBeforeAllocation) {
  model::WorldDescription world = test::square_room(6.0);
  world.size = {200.0, 200.0};
  // 200 m at 0.05 m: 4000 x 4000 = 16 000 000 cells, within 4096 x 4096 = 16 777 216.
  EXPECT_DOUBLE_EQ(map_cell_count(world, 0.05), 16e6);
  EXPECT_NO_THROW(check_map_size(world, 0.05));
  // At 0.01 m: 20000 x 20000 = 4e8 cells, refused with the numbers.
  try {
    rasterize_static_map(world, 0.01);
    FAIL() << "a 4e8-cell grid was allocated";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "map_resolution: 0.01 m over the floor of world 'room' (200 x 200 m) gives 4e+08 "
              "cells, more than the 16777216 an occupancy grid may have");
  }
  // Sizes that reach the grid without model::WorldDescription::validate (C++ callers) are caught
  // too.
  world.size = {3000.0, 3000.0};
  EXPECT_THROW(rasterize_static_map(world, 0.05), core::ConfigError);
  EXPECT_THROW(check_map_size(world, std::nan("")), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::world
