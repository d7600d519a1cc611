// from_msg(to_msg(snapshot)) gives back what the world core reported, so scenario_node's script
// sees over ROS what the batch tool's sees in-process.
#include <gtest/gtest.h>

#include "../../src/nodes/conversions/world_state.hpp"
#include "ari_social_sim/world/scene.hpp"

namespace ari_social_sim::nodes {
namespace {

TEST(WorldStateRoundTrip, EveryFieldComesBack) {
  const world::Scene scene =
      world::load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/waiting_room.yaml");
  auto simulation = world::build_simulation(scene, world::SimulationConfig{});
  simulation->ari()->speech().say("GREETING", "Hello I am ARI", 0.0);
  simulation->humans().front()->speech().say("request(location(toilet))", "Where is it", 0.0);
  for (int i = 0; i < 60; ++i) {
    simulation->step();
  }
  const world::WorldSnapshot a = world::WorldSnapshot::of(*simulation);
  const world::WorldSnapshot b = from_msg(to_msg(a, "map"));
  EXPECT_DOUBLE_EQ(b.time_s, a.time_s);  // 3 s: exact in ros::Time's nanoseconds
  EXPECT_EQ(b.step, a.step);
  ASSERT_TRUE(b.ari.has_value());
  EXPECT_EQ(b.ari->pose.position, a.ari->pose.position);
  EXPECT_EQ(b.ari->speech.previous_act, "GREETING");
  ASSERT_EQ(b.humans.size(), a.humans.size());
  for (size_t i = 0; i < a.humans.size(); ++i) {
    const world::HumanSnapshot& x = a.humans[i];
    const world::HumanSnapshot& y = b.humans[i];
    EXPECT_EQ(y.id, x.id);
    EXPECT_EQ(y.name, x.name);
    EXPECT_EQ(y.role, x.role);
    EXPECT_EQ(y.pose.position, x.pose.position);
    EXPECT_EQ(y.pose.theta, x.pose.theta);
    EXPECT_EQ(y.velocity_mps, x.velocity_mps);
    EXPECT_FLOAT_EQ(static_cast<float>(y.age_years), static_cast<float>(x.age_years));
    EXPECT_EQ(y.gender, x.gender);
    EXPECT_EQ(y.emotion, x.emotion);
    EXPECT_EQ(y.motion_mode, x.motion_mode);
    EXPECT_EQ(y.goal.has_value(), x.goal.has_value());
    EXPECT_EQ(y.group_id, x.group_id);
    EXPECT_EQ(y.gaze.target, x.gaze.target);
    EXPECT_EQ(y.speech.act, x.speech.act);
    EXPECT_EQ(y.speech.is_speaking, x.speech.is_speaking);
    EXPECT_EQ(y.speech.start_s, x.speech.start_s);
    EXPECT_EQ(y.speech.previous_act, x.speech.previous_act);
  }
  ASSERT_EQ(b.groups.size(), a.groups.size());
  EXPECT_EQ(b.groups[0].members, a.groups[0].members);
  EXPECT_EQ(b.groups[0].centre, a.groups[0].centre);
}

}  // namespace
}  // namespace ari_social_sim::nodes
