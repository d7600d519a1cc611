// rendering::floor_shade: the soft shade furniture casts on the floor, under seats and table tops
// and round what stands on it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/floor_shade.hpp"
#include "ari_social_sim/rendering/furniture.hpp"
#include "ari_social_sim/rendering/world_scene.hpp"
#include "render_test_scenes.hpp"

namespace ari_social_sim::rendering {
namespace {

TEST(FloorShade, ASeatShadesTheFloorBeneathItAsMuchAsTheSkyItCovers) {
  // A chair's seat, 0.46 x 0.5 m, its underside 0.42 m up: it covers R^2 / (R^2 + h^2) = 0.25 of
  // the sky over the floor beneath its centre, twice that of the light.
  const RenderPrimitive seat = test::box({1.0, 2.0, 0.45}, {0.46, 0.5, 0.06});
  const std::vector<FloorOccluder> occluders = floor_occluders_of({seat});
  ASSERT_EQ(occluders.size(), 1u);
  const double r2 = 0.23 * 0.25, h2 = 0.42 * 0.42;
  EXPECT_NEAR(floor_openness(occluders, {1.0, 2.0}), 1.0 - 2.0 * r2 / (r2 + h2), 1e-9);
  // Half its height beyond its edge the shade is e^-1 of that; a metre away it is gone.
  EXPECT_NEAR(floor_openness(occluders, {1.0 + 0.23 + 0.21, 2.0}),
              1.0 - 2.0 * r2 / (r2 + h2) * std::exp(-1.0), 1e-9);
  EXPECT_GT(floor_openness(occluders, {2.2, 2.0}), 0.999);
}

TEST(FloorShade, WhatStandsOnTheFloorDarkensARimRoundItsFoot) {
  // A dispenser cabinet 0.3 x 0.2 m, turned 90 degrees: its long side along y.
  const RenderPrimitive cabinet = test::box({0.0, 0.0, 0.5}, {0.3, 0.2, 1.0}, M_PI / 2);
  const std::vector<FloorOccluder> occluders = floor_occluders_of({cabinet});
  ASSERT_EQ(occluders.size(), 1u);
  EXPECT_NEAR(occluders[0].distance_to({0.0, 0.15}), 0.0, 1e-9);  // inside: its long side is y
  EXPECT_NEAR(occluders[0].distance_to({0.3, 0.0}), 0.2, 1e-9);
  EXPECT_NEAR(floor_openness(occluders, {0.1, 0.0}), 0.65, 1e-9);  // at its side
  EXPECT_GT(floor_openness(occluders, {0.45, 0.0}), 0.99);         // 0.35 m from it
}

TEST(FloorShade, WallsLampsLegsAndHighThingsCastNone) {
  RenderPrimitive wall = test::box({0.0, 0.0, 1.5}, {0.2, 6.0, 3.0});
  wall.surface = Surface::kWall;
  RenderPrimitive lamp = test::box({0.0, 0.0, 2.7}, {0.6, 1.2, 0.02});
  lamp.surface = Surface::kLamp;
  RenderPrimitive leg = test::box({0.0, 0.0, 0.2}, {0.04, 0.04, 0.4});
  leg.shape = PrimitiveShape::kCylinder;
  const RenderPrimitive shelf = test::box({0.0, 0.0, 1.6}, {0.4, 1.0, 0.03});
  EXPECT_TRUE(floor_occluders_of({wall, lamp, leg, shelf}).empty());
}

TEST(FloorShade, ShadingAFloorScalesItsVerticesColourAsTheLightWould) {
  RenderPrimitive floor = test::box({0.0, 0.0, -0.01}, {4.0, 4.0, 0.02});
  floor.surface = Surface::kFloor;
  floor.max_facet_m = 0.125;
  RenderMesh mesh = mesh_of({floor});
  const RenderMesh unshaded = mesh;
  const std::vector<FloorOccluder> occluders =
      floor_occluders_of({test::box({0.0, 0.0, 0.45}, {0.46, 0.5, 0.06})});
  shade_floor(occluders, mesh);
  int checked = 0;
  for (size_t i = 0; i < mesh.vertices.size(); i += RenderMesh::kFloatsPerVertex) {
    const Eigen::Vector2d at(mesh.vertices[i], mesh.vertices[i + 1]);
    const double shade = std::pow(floor_openness(occluders, at), 1.0 / 2.2);
    const int red = RenderMesh::kColourOffset;
    ASSERT_NEAR(mesh.vertices[i + red], unshaded.vertices[i + red] * shade, 1e-6);
    checked += shade < 0.9 ? 1 : 0;
  }
  EXPECT_GT(checked, 0);  // some vertices lie in the seat's shade
}

TEST(FloorShade, TheWaitingRoomsChairsShadeTheFloorUnderEachSeat) {
  const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  const std::vector<RenderPrimitive> parts = static_primitives_of(world, SceneStyle{});
  const std::vector<FloorOccluder> occluders = floor_occluders_of(parts);
  int seats = 0;
  double darkest = 1.0, lightest = 0.0;
  for (const RenderPrimitive& part : parts) {
    const double z = part.X_world_shape.translation().z();
    if (std::abs(z - (kChairSeatHeightM - 0.03)) < 1e-6 && part.size.z() < 0.1) {  // a seat
      const double open = floor_openness(occluders, part.X_world_shape.translation().head<2>());
      darkest = std::min(darkest, open);
      lightest = std::max(lightest, open);
      ++seats;
    }
  }
  std::printf("[ measured ] %d seats: floor beneath them gets %.2f-%.2f of the light\n", seats,
              darkest, lightest);
  ASSERT_GT(seats, 10);
  EXPECT_GT(darkest, 0.3);
  EXPECT_LT(lightest, 0.65);
}

}  // namespace
}  // namespace ari_social_sim::rendering
