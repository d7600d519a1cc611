// /sim/world_state read back: from_msg(to_msg(snapshot)) is the snapshot, so what
// hri_perception_node perceives over the wire is what the world core produced.
#include <gtest/gtest.h>

#include "../../src/nodes/conversions/world_state.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/scene.hpp"

namespace ari_social_sim::nodes {
namespace {

TEST(WorldStateConversion, SnapshotSurvivesTheMessage) {
  const world::Scene scene =
      world::load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/waiting_room.yaml");
  auto simulation = world::build_simulation(scene, world::SimulationConfig{});
  simulation->find_human(20)->speech().say("INFORM", "over there by the window", 0.0);
  for (int i = 0; i < 30; ++i) {
    simulation->step();
  }
  const world::WorldSnapshot truth = world::WorldSnapshot::of(*simulation);
  const world::WorldSnapshot back = from_msg(to_msg(truth, "map"));
  EXPECT_DOUBLE_EQ(back.time_s, truth.time_s);
  EXPECT_EQ(back.step, truth.step);
  ASSERT_TRUE(back.ari.has_value());
  EXPECT_EQ(back.ari->pose.position, truth.ari->pose.position);
  EXPECT_EQ(back.ari->head_pan_rad, truth.ari->head_pan_rad);
  ASSERT_EQ(back.humans.size(), truth.humans.size());
  for (size_t i = 0; i < truth.humans.size(); ++i) {
    const world::HumanSnapshot& a = truth.humans[i];
    const world::HumanSnapshot& b = back.humans[i];
    EXPECT_EQ(b.id, a.id);
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.pose.position, a.pose.position);
    EXPECT_EQ(b.pose.theta, a.pose.theta);
    EXPECT_EQ(b.velocity_mps, a.velocity_mps);
    EXPECT_FLOAT_EQ(b.age_years, a.age_years);  // float32 on the wire
    EXPECT_EQ(b.gender, a.gender);
    EXPECT_EQ(b.mask, a.mask);
    EXPECT_EQ(b.emotion, a.emotion);
    EXPECT_EQ(b.goal.has_value(), a.goal.has_value());
    EXPECT_EQ(b.group_id, a.group_id);
    EXPECT_EQ(b.gaze.target, a.gaze.target);
    EXPECT_EQ(b.gaze.direction_rad, a.gaze.direction_rad);
    EXPECT_EQ(b.speech.content, a.speech.content);
    EXPECT_EQ(b.speech.word_index, a.speech.word_index);
    EXPECT_EQ(b.speech.is_speaking, a.speech.is_speaking);
    EXPECT_EQ(b.speech.start_s, a.speech.start_s);
  }
  EXPECT_TRUE(back.humans[2].speech.is_speaking);  // human 20
  ASSERT_EQ(back.groups.size(), truth.groups.size());
  EXPECT_EQ(back.groups[1].members, truth.groups[1].members);

  const world::OccupancyGrid grid = world::rasterize_static_map(scene.world, 0.05);
  const world::OccupancyGrid grid_back = from_msg(to_msg(grid, "map", 0.0));
  EXPECT_EQ(grid_back.cells, grid.cells);
  EXPECT_EQ(grid_back.width, grid.width);
  EXPECT_NEAR(grid_back.resolution_m, 0.05, 1e-7);  // float32 on the wire
  EXPECT_EQ(grid_back.origin, grid.origin);
}

}  // namespace
}  // namespace ari_social_sim::nodes
