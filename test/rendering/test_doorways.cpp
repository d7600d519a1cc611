// rendering::doorways_of: the gaps world files leave in walls for doors get a frame and the wall
// above them, where they showed the sky up to the ceiling.
#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/doorways.hpp"

namespace ari_social_sim::rendering {
namespace {

TEST(Doorways, TheWaitingRoomsEntranceAndCorridorDoorGetAFrameAndALintel) {
  const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  const std::vector<Doorway> doorways = doorways_of(world, model::kDefaultWallHeightM);
  // The entrance, x 5.0 to 6.4 in the south wall; the corridor door, y 6.0 to 7.4 in the east
  // wall (the world file's comment).
  ASSERT_EQ(doorways.size(), 2u);
  for (const Doorway& doorway : doorways) {
    EXPECT_NEAR(doorway.width_m, 1.4, 1e-9);
    EXPECT_NEAR(doorway.wall_thickness_m, 0.1, 1e-9);
    const bool south = std::abs(doorway.centre.y()) < 1e-9;
    EXPECT_TRUE(south || std::abs(doorway.centre.x() - 12.0) < 1e-9);
    EXPECT_NEAR(south ? doorway.centre.x() : doorway.centre.y(), south ? 5.7 : 6.7, 1e-9);

    const std::vector<RenderPrimitive> parts = doorway_primitives(doorway, {0.8f, 0.8f, 0.8f});
    ASSERT_EQ(parts.size(), 4u);  // lintel, two jambs, head
    const RenderPrimitive& lintel = parts[0];
    EXPECT_EQ(lintel.surface, Surface::kWall);
    EXPECT_NEAR(lintel.X_world_shape.translation().z() - 0.5 * lintel.size.z(), kDoorHeightM, 1e-9);
    EXPECT_NEAR(lintel.X_world_shape.translation().z() + 0.5 * lintel.size.z(),
                model::kDefaultWallHeightM, 1e-9);
    EXPECT_NEAR(lintel.size.x(), 1.4, 1e-9);
    // The jambs leave a clear width of 1.4 - 2 x 0.06 m between them.
    const double between =
        (parts[2].X_world_shape.translation() - parts[1].X_world_shape.translation())
            .head<2>()
            .norm() -
        parts[1].size.x();
    EXPECT_NEAR(between, 1.28, 1e-9);
  }
}

TEST(Doorways, OnlyGapsOfADoorsWidthBetweenWallsOnOneLine) {
  model::WorldDescription world;
  auto wall = [](double x0, double x1, double y, double yaw_deg) {
    model::StaticObject w;
    w.type = model::ShapeType::kWall;
    w.pose = {{0.5 * (x0 + x1), y}, yaw_deg * M_PI / 180.0};
    w.size = {x1 - x0, 0.1};
    return w;
  };
  world.objects = {wall(0.0, 2.0, 0.0, 0.0),    wall(2.9, 5.0, 0.0, 0.0),  // 0.9 m: a door
                   wall(5.3, 6.0, 0.0, 0.0),                               // 0.3 m: too narrow
                   wall(9.0, 10.0, 0.0, 0.0),                              // 3 m: an open side
                   wall(10.5, 11.0, 0.05, 0.0),                            // 5 cm off the line
                   wall(11.5, 12.0, 0.0, 5.0)};                            // turned 5 degrees
  const std::vector<Doorway> doorways = doorways_of(world, 2.5);
  ASSERT_EQ(doorways.size(), 1u);
  EXPECT_NEAR(doorways[0].width_m, 0.9, 1e-9);
  EXPECT_NEAR(doorways[0].centre.x(), 2.45, 1e-9);
}

}  // namespace
}  // namespace ari_social_sim::rendering
