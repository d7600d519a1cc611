#include <gtest/gtest.h>

#include "ari_social_sim/perception/grid_raycast.hpp"
#include "ari_social_sim/perception/sound_map.hpp"
#include "ari_social_sim/world/map_sensor.hpp"

namespace ari_social_sim::perception {
namespace {

TEST(SoundMap, WallsBlockSoundFurnitureDoesNot) {
  model::WorldDescription world;
  world.origin = {0.0, 0.0};
  world.size = {10.0, 10.0};
  model::StaticObject wall;
  wall.id = 1;
  wall.type = model::ShapeType::kWall;
  wall.pose = {{5.0, 5.0}, 1.5708};
  wall.size = {4.0, 0.1};
  model::StaticObject desk;
  desk.id = 2;
  desk.type = model::ShapeType::kBox;
  desk.pose = {{2.0, 2.0}, 0.0};
  desk.size = {1.0, 1.0};
  world.objects = {wall, desk};
  const model::OccupancyGrid sight = world::rasterize_static_map(world, 0.05);
  const model::OccupancyGrid sound = rasterize_walls(world, 0.05);
  // Across the wall (x = 5, y 3..7): blocked for both.
  EXPECT_FALSE(segment_is_clear(sight, 50, {3.0, 5.0}, {7.0, 5.0}));
  EXPECT_FALSE(segment_is_clear(sound, 50, {3.0, 5.0}, {7.0, 5.0}));
  // Across the desk (1.5..2.5): blocks sight, not sound.
  EXPECT_FALSE(segment_is_clear(sight, 50, {0.5, 2.0}, {3.5, 2.0}));
  EXPECT_TRUE(segment_is_clear(sound, 50, {0.5, 2.0}, {3.5, 2.0}));
  EXPECT_EQ(sound.width, sight.width);
  EXPECT_EQ(sound.origin, sight.origin);
}

}  // namespace
}  // namespace ari_social_sim::perception
