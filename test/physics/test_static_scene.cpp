// StaticScene: a world file's walls and furniture as solids on the floor.

#include <gtest/gtest.h>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/static_scene.hpp"

namespace ari_social_sim::physics {
namespace {

TEST(StaticScene, ExtrudesEveryShapeToItsHeight) {
  const model::WorldDescription world = model::parse_world(core::YamlMap::parse(
      "name: t\norigin: [-1, -2]\nsize: [8, 6]\nobjects:\n"
      "  - {type: wall, from: [0, 0], to: [0, 4], thickness: 0.1}\n"
      "  - {type: box, position: [2, 2], orientation: 0.5, size: [1, 0.5], height: 1.1}\n"
      "  - {type: circle, position: [3, 1], radius: 0.3}\n"
      "  - {type: polygon, points: [[4, 0], [5, 0], [5, 1]], height: 0.4}\n",
      "inline"));
  const StaticScene scene = StaticScene::from_world(world);
  EXPECT_EQ(scene.floor_origin, Eigen::Vector2d(-1, -2));
  ASSERT_EQ(scene.solids.size(), 4u);
  // The wall: 4 m long along +y (turned 90 degrees), 0.1 m thick, 2.5 m high, centred at 1.25 m.
  const SceneSolid& wall = scene.solids[0];
  EXPECT_TRUE(wall.is_wall);
  EXPECT_TRUE(wall.box_size_m.isApprox(Eigen::Vector3d(4.0, 0.1, 2.5)));
  EXPECT_TRUE(wall.X_map_solid.translation().isApprox(Eigen::Vector3d(0, 2, 1.25)));
  EXPECT_NEAR(wall.X_map_solid.linear()(1, 0), 1.0, 1e-12);
  EXPECT_NEAR(scene.solids[1].X_map_solid.translation().z(), 0.55, 1e-12);
  EXPECT_EQ(scene.solids[2].type, SceneSolid::Type::kCylinder);
  EXPECT_DOUBLE_EQ(scene.solids[2].height_m, 0.75);
  EXPECT_EQ(scene.solids[3].footprint.size(), 3u);
  EXPECT_DOUBLE_EQ(scene.solids[3].height_m, 0.4);
}

}  // namespace
}  // namespace ari_social_sim::physics
