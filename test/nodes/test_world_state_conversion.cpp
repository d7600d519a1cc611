// /sim/world_state read back: from_msg(to_msg(snapshot)) is the snapshot, so what
// hri_perception_node perceives over the wire is what the world core produced.
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "ari_social_sim/core/clock_time.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

TEST(WorldStateConversion, SnapshotSurvivesTheMessage) {
  const world::Scene scene =
      world::load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/waiting_room.yaml");
  auto simulation = world::build_simulation(scene, world::SimulationConfig{});
  simulation->say(20, "INFORM", "over there by the window");
  simulation->set_human_reaction(21, world::ReactionProfile::kAvoid);
  // Patient 30 walks to reception: the length of her path, step by step.
  double path_m = 0.0;
  for (int i = 0; i < 30; ++i) {
    const Eigen::Vector2d before = world::WorldSnapshot::of(*simulation).humans[5].pose.position;
    simulation->step();
    path_m += (world::WorldSnapshot::of(*simulation).humans[5].pose.position - before).norm();
  }
  const world::WorldSnapshot truth = world::WorldSnapshot::of(*simulation);
  ASSERT_EQ(truth.humans[5].id, 30u);
  EXPECT_GT(path_m, 0.5);
  EXPECT_NEAR(truth.humans[5].walked_m, path_m, 0.01 * path_m);
  const world::WorldSnapshot back = from_msg(to_msg(truth, "map"));
  EXPECT_EQ(back.time_s, truth.time_s);
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
    EXPECT_EQ(b.age_years, a.age_years);  // float32 on the wire, which holds whole years
    EXPECT_EQ(b.gender, a.gender);
    EXPECT_EQ(b.mask, a.mask);
    EXPECT_EQ(b.emotion, a.emotion);
    EXPECT_EQ(b.goal.has_value(), a.goal.has_value());
    EXPECT_EQ(b.group_id, a.group_id);
    EXPECT_EQ(b.reaction, a.reaction);
    EXPECT_EQ(b.gaze.target, a.gaze.target);
    EXPECT_EQ(b.gaze.direction_rad, a.gaze.direction_rad);
    EXPECT_EQ(b.speech.content, a.speech.content);
    EXPECT_EQ(b.speech.word_index, a.speech.word_index);
    EXPECT_EQ(b.speech.is_speaking, a.speech.is_speaking);
    EXPECT_EQ(b.speech.start_s, a.speech.start_s);
    EXPECT_EQ(b.speech.words_per_minute, a.speech.words_per_minute);
    EXPECT_EQ(b.walked_m, a.walked_m);
  }

  EXPECT_TRUE(back.humans[2].speech.is_speaking);  // human 20
  // Human 21 avoids ARI.
  EXPECT_EQ(back.humans[3].reaction, world::ReactionProfile::kAvoid);
  ASSERT_EQ(back.groups.size(), truth.groups.size());
  EXPECT_EQ(back.groups[1].members, truth.groups[1].members);

  const model::OccupancyGrid grid = world::rasterize_static_map(scene.world, 0.05);
  const model::OccupancyGrid grid_back = from_msg(to_msg(grid, "map", 0.0));
  EXPECT_EQ(grid_back.cells, grid.cells);
  EXPECT_EQ(grid_back.width, grid.width);
  // float32 on the wire, as the grid has it from the start.
  EXPECT_EQ(grid_back.resolution_m, grid.resolution_m);
  EXPECT_NEAR(grid.resolution_m, 0.05, 1e-8);
  EXPECT_EQ(grid_back.origin, grid.origin);
}

// Sim time in whole nanoseconds: the stamp of every step reads back the world's time exactly,
// whatever the step (a double count of 0.05 s steps would not: 0.15000000000000002 s reads back
// as 0.15 s).
TEST(WorldStateConversion, EveryStepsStampReadsBackTheSimTimeExactly) {
  for (const double step_s : {0.05, 0.01, 0.02, 1.0 / 30.0}) {
    int differing = 0;
    for (uint64_t step = 0; step <= 200000; ++step) {  // 2.8 h of 0.05 s steps
      const double time_s = core::clock_time_s(step, step_s);
      differing += ros::Time(time_s).toSec() != time_s;
    }
    EXPECT_EQ(differing, 0) << "steps of " << step_s << " s";
  }
  EXPECT_EQ(core::clock_time_s(3, 0.05), ros::Time(0, 150000000).toSec());
  EXPECT_EQ(core::clock_time_s(20 * 3600, 0.05), 3600.0);
}

// The waiting room's state after a second, as world_node publishes it.
WorldState waiting_room_state() {
  const world::Scene scene =
      world::load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/waiting_room.yaml");
  auto simulation = world::build_simulation(scene, world::SimulationConfig{});
  for (int i = 0; i < 20; ++i) {
    simulation->step();
  }
  return to_msg(world::WorldSnapshot::of(*simulation), "map");
}

std::string describe(const std::optional<InputProblem>& problem) {
  return problem ? problem->field + ": " + problem->what : "fine";
}

TEST(WorldStateInput, EveryNumberTheConsumersUseMustBeFiniteAndEnumsKnown) {
  const WorldState good = waiting_room_state();
  ASSERT_GE(good.humans.size(), 3u);
  EXPECT_EQ(describe(input_problem(good)), "fine");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::function<void(WorldState&)>, std::string>> cases = {
      {[&](WorldState& m) { m.ari.pose.x = nan; }, "ari.pose.x: nan, not a finite number"},
      {[&](WorldState& m) { m.ari.head_pan = -inf; }, "ari.head_pan: -inf, not a finite number"},
      {[&](WorldState& m) { m.humans[2].pose.theta = nan; },
       "humans[2].pose.theta: nan, not a finite number"},
      {[&](WorldState& m) { m.humans[1].velocity.linear.y = inf; },
       "humans[1].velocity.linear.y: inf, not a finite number"},
      {[&](WorldState& m) { m.humans[0].age = std::numeric_limits<float>::quiet_NaN(); },
       "humans[0].age: nan, not a finite number"},
      {[&](WorldState& m) { m.humans[0].gender = 7; }, "humans[0].gender: 7, not one of 1..3"},
      {[&](WorldState& m) { m.humans[1].emotion = 4; }, "humans[1].emotion: 4, not one of 0..3"},
      {[&](WorldState& m) { m.humans[1].motion_mode = 200; },
       "humans[1].motion_mode: 200, not one of 0..3"},
      {[&](WorldState& m) { m.humans[0].gaze.direction = nan; },
       "humans[0].gaze.direction: nan, not a finite number"},
      {[&](WorldState& m) { m.humans[2].walked_distance = -0.5; },
       "humans[2].walked_distance: -0.5, not a finite distance of 0 m or more"},
      {[&](WorldState& m) { m.humans[0].walked_distance = nan; },
       "humans[0].walked_distance: nan, not a finite distance of 0 m or more"},
      {[&](WorldState& m) { m.humans[1].reaction = "shy"; },
       "humans[1].reaction: 'shy', not one of ignore, yield, curious, avoid or block"},
      {[&](WorldState& m) { m.groups.at(0).ospace_radius = nan; },
       "groups[0].ospace_radius: nan, not a finite number"},
      {[&](WorldState& m) { m.humans.resize(world::kMaxHumans + 1, m.humans[0]); },
       "humans (count): 1001, more than 1000"}};
  for (const auto& [spoil, expected] : cases) {
    WorldState bad = good;
    spoil(bad);
    EXPECT_EQ(describe(input_problem(bad)), expected);
  }
  // A NaN in ARI's pose does not count when the message says there is no ARI.
  WorldState without_ari = good;
  without_ari.has_ari = false;
  without_ari.ari.pose.x = nan;
  EXPECT_EQ(describe(input_problem(without_ari)), "fine");
}

TEST(MapInput, CellsMustMatchTheSizeAndStayWithinTheLimit) {
  model::OccupancyGrid grid;
  grid.resolution_m = 0.05;
  grid.width = 40;
  grid.height = 30;
  grid.cells.assign(1200, 0);
  const nav_msgs::OccupancyGrid good = to_msg(grid, "map", 0.0);
  EXPECT_EQ(describe(input_problem(good)), "fine");
  nav_msgs::OccupancyGrid bad = good;
  bad.data.pop_back();
  EXPECT_EQ(describe(input_problem(bad)), "data: 1199 cells for a 40 x 30 grid");
  bad = good;
  bad.info.resolution = 0.0f;
  EXPECT_EQ(describe(input_problem(bad)), "info.resolution: 0.000000, not > 0");
  bad = good;
  bad.info.origin.position.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(describe(input_problem(bad)), "info.origin.position.y: nan, not a finite number");
  bad = good;
  bad.info.width = 100000;
  bad.info.height = 100000;  // 1e10 cells: refused before anything is allocated from it
  EXPECT_EQ(describe(input_problem(bad)),
            "info.width x info.height: 10000000000, more than 16777216");
}

}  // namespace
}  // namespace ari_social_sim::nodes
