#include <gtest/gtest.h>

#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

TEST(MapSensor, RasterisesWallsAndFurnitureButNotAgents) {
  WorldDescription world = test::square_room(6.0);
  StaticObject table;
  table.id = 50;
  table.type = ShapeType::kCircle;
  table.pose.position = {4.0, 4.0};
  table.radius_m = 0.5;
  world.objects.push_back(table);
  const OccupancyGrid grid = rasterize_static_map(world, 0.05);
  // Floor 6.4 m at 0.05 m: 128 x 128 cells from (-0.2, -0.2).
  EXPECT_EQ(grid.width, 128);
  EXPECT_EQ(grid.height, 128);
  auto occupied = [&](double x, double y) {
    int cx, cy;
    EXPECT_TRUE(grid.cell_of({x, y}, cx, cy));
    return grid.at(cx, cy) == OccupancyGrid::kOccupied;
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

}  // namespace
}  // namespace ari_social_sim::world
