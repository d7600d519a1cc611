// The batch engine's world requests (Episode's in-process commands) are the world core's request
// API: a script's spawn, group, goal, gaze and speech requests leave the world exactly as the same
// requests sent to a twin world through Simulation, as world_node's services send them.
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::engine {
namespace {

const std::string kSource = ARI_SOURCE_DIR;
constexpr uint64_t kSeed = 5;
constexpr int kSteps = 200;  // 10 s

// room_6x6 with ARI, Ana (10) and Luc (11) in group 1; on entering its only state the script
// spawns Zoe (12, walking, looking at Ana) and Max (13, curious about ARI), moves Max and Luc into
// a new group 2 where Max sits down, sends Ana walking (which drops group 1), lets her speak, and
// spawns and removes Eve (14).
scenario::Scenario requests_scenario() {
  const std::string text =
      "world: " + kSource +
      "/worlds/room_6x6.yaml\nseed: 1\n"
      "ari: {position: [1, 5], orientation: -1.57}\n"
      "humans:\n"
      "  - {id: 10, name: Ana, position: [3, 3]}\n"
      "  - {id: 11, name: Luc, position: [4, 3]}\n"
      "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3]}\n"
      "script:\n"
      "  time_limit: 60\n"
      "  start: s\n"
      "  states:\n"
      "    - name: s\n"
      "      enter:\n"
      "        - {type: add_human, human: {id: 12, position: [1, 1], goal: {position: [5, 1]}, "
      "gaze: {mean_duration: 2, targets: [{id: 10, probability: 1.0}]}}}\n"
      "        - {type: add_human, human: {id: 13, position: [5, 5], reaction: curious}}\n"
      "        - {type: create_group, group: {id: 2, members: [13], centre: [4.5, 4.5]}}\n"
      "        - {type: add_group_members, group: 2, members: [11]}\n"
      "        - {type: set_group_centre, group: 2, centre: [4, 4.5]}\n"
      "        - {type: set_posture, who: 13, posture: sitting}\n"
      "        - {type: set_goal, who: 10, position: [2, 4.5]}\n"
      "        - {type: say, speaker: 10, act: INFORM, text: over there by the window}\n"
      "        - {type: add_human, human: {id: 14, position: [1, 3]}}\n"
      "        - {type: remove_human, human: 14}\n";
  return scenario::parse_scenario(core::YamlMap::parse(text, "inline.yaml"), kSource, "requests");
}

// The same requests through the world's API, in the order scenario_node sends them to
// world_node's services (a spawn's goal, gaze and reaction follow as set_goal, set_gaze_targets
// and set_reaction).
void send_requests(world::Simulation& world) {
  world::HumanSpec zoe;
  zoe.id = 12;
  zoe.pose.position = {1.0, 1.0};
  world.add_human(zoe);
  world.set_human_goal(12, {{5.0, 1.0}, 0.0});
  world::GazeModel gaze;
  gaze.targets = {{10, 1.0}};
  gaze.mean_duration_s = 2.0;
  world.set_human_gaze(12, gaze);
  world::HumanSpec max;
  max.id = 13;
  max.pose.position = {5.0, 5.0};
  world.add_human(max);
  world.set_human_reaction(13, world::ReactionProfile::kCurious);
  world::GroupSpec group;
  group.id = 2;
  group.members = {13};
  group.centre = {4.5, 4.5};
  world.add_group(group);
  world.add_group_members(2, {11});
  world.set_group_centre(2, {4.0, 4.5});
  world.set_human_posture(13, world::Posture::kSitting);
  world.set_human_goal(10, {{2.0, 4.5}, 0.0});
  world.say(10, "INFORM", "over there by the window");
  world::HumanSpec eve;
  eve.id = 14;
  eve.pose.position = {1.0, 3.0};
  world.add_human(eve);
  world.remove_human(14);
}

// The episode of `scenario` and a twin world built from its scene with the same seed, run side by
// side for kSteps. The script enters its first state after the first step: `send_requests` then
// gives the twin what the script asks for on entering it.
struct SideBySide {
  std::unique_ptr<Episode> episode;
  std::unique_ptr<world::Simulation> twin;
};

SideBySide run_side_by_side(const scenario::Scenario& scenario,
                            const std::function<void(world::Simulation&)>& send_requests) {
  static const EpisodeConfig config = EpisodeConfig::load(kSource + "/config");
  SideBySide run;
  run.episode = std::make_unique<Episode>(scenario, kSeed, config);
  world::Scene scene = scenario.scene;
  scene.seed = kSeed;
  run.twin = world::build_simulation(scene, config.simulation);
  run.twin->set_conversation_lines(config.conversation_lines);  // as the engine's groups talk
  run.twin->step();
  run.episode->step();
  send_requests(*run.twin);
  for (int i = 1; i < kSteps; ++i) {
    run.twin->step();
    run.episode->step();
  }
  return run;
}

TEST(EpisodeRequests, TheInProcessCommandsLeaveTheWorldAsTheWorldsApiDoes) {
  const scenario::Scenario scenario = requests_scenario();
  const SideBySide run = run_side_by_side(scenario, send_requests);
  const world::WorldSnapshot in_process = world::WorldSnapshot::of(run.episode->simulation());
  const world::WorldSnapshot direct = world::WorldSnapshot::of(*run.twin);
  EXPECT_DOUBLE_EQ(in_process.time_s, 10.0);
  ASSERT_EQ(in_process.humans.size(), 4u);  // 10-13: Eve came and went
  ASSERT_EQ(direct.humans.size(), 4u);
  for (size_t i = 0; i < direct.humans.size(); ++i) {
    const world::HumanSnapshot& a = in_process.humans[i];
    const world::HumanSnapshot& b = direct.humans[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.pose.position.x(), b.pose.position.x()) << "human " << b.id;
    EXPECT_EQ(a.pose.position.y(), b.pose.position.y()) << "human " << b.id;
    EXPECT_EQ(a.pose.theta, b.pose.theta) << "human " << b.id;
    EXPECT_EQ(a.motion_mode, b.motion_mode) << "human " << b.id;
    EXPECT_EQ(a.group_id, b.group_id) << "human " << b.id;
    EXPECT_EQ(a.gaze.target, b.gaze.target) << "human " << b.id;
    EXPECT_EQ(a.reaction, b.reaction) << "human " << b.id;
    EXPECT_EQ(a.speech.previous_act, b.speech.previous_act) << "human " << b.id;
    EXPECT_EQ(a.posture.posture, b.posture.posture) << "human " << b.id;
    EXPECT_EQ(a.posture.progress, b.posture.progress) << "human " << b.id;
    EXPECT_EQ(a.walked_m, b.walked_m) << "human " << b.id;
  }
  // Zoe walked her 4 m east and looks at Ana; Ana walked north out of group 1, which was dropped;
  // group 2 is Max and Luc.
  EXPECT_NEAR(direct.humans[2].pose.position.x(), 5.0, 0.1);
  EXPECT_EQ(direct.humans[2].gaze.target, 10u);
  EXPECT_NEAR(direct.humans[0].pose.position.y(), 4.5, 0.1);
  EXPECT_EQ(direct.humans[0].speech.previous_act, "INFORM");
  EXPECT_EQ(direct.humans[3].reaction, world::ReactionProfile::kCurious);
  EXPECT_EQ(direct.humans[3].posture.posture, world::Posture::kSitting);  // Max, settled
  EXPECT_EQ(direct.humans[3].posture.progress, 1.0);
  ASSERT_EQ(in_process.groups.size(), 1u);
  EXPECT_EQ(in_process.groups[0].id, 2u);
  EXPECT_EQ(in_process.groups[0].members, (std::vector<model::ObjectId>{13, 11}));
  EXPECT_DOUBLE_EQ(in_process.groups[0].centre.x(), 4.0);
}

// A script's create_walking_group is the world's add_walking_group: Ana (10) and Luc (11) walk
// abreast across room_6x6 and form a vis-a-vis conversation group at the goal, step for step as
// in a twin world given the request directly.
TEST(EpisodeRequests, AWalkingGroupWalksAsTheWorldsApiMakesIt) {
  const std::string text =
      "world: " + kSource +
      "/worlds/room_6x6.yaml\nseed: 1\n"
      "humans:\n"
      "  - {id: 10, name: Ana, position: [1, 1.6]}\n"
      "  - {id: 11, name: Luc, position: [1, 0.85]}\n"
      "script:\n"
      "  time_limit: 60\n"
      "  start: s\n"
      "  states:\n"
      "    - name: s\n"
      "      enter:\n"
      "        - {type: create_walking_group, group: {id: 2, members: [10, 11], goal: {position: "
      "[4.5, 4.5]}, on_arrival: converse, arrangement: vis-a-vis}}\n";
  const scenario::Scenario scenario =
      scenario::parse_scenario(core::YamlMap::parse(text, "inline.yaml"), kSource, "walking");
  const SideBySide run = run_side_by_side(scenario, [](world::Simulation& twin) {
    world::WalkingGroupSpec walking;
    walking.id = 2;
    walking.members = {10, 11};
    walking.goal.position = {4.5, 4.5};
    walking.on_arrival = world::ArrivalAction::kConverse;
    walking.arrangement = model::Arrangement::kVisAVis;
    twin.add_walking_group(walking);
  });
  const world::WorldSnapshot in_process = world::WorldSnapshot::of(run.episode->simulation());
  const world::WorldSnapshot direct = world::WorldSnapshot::of(*run.twin);
  ASSERT_EQ(in_process.humans.size(), 2u);
  for (size_t i = 0; i < direct.humans.size(); ++i) {
    EXPECT_EQ(in_process.humans[i].pose.position, direct.humans[i].pose.position);
    EXPECT_EQ(in_process.humans[i].pose.theta, direct.humans[i].pose.theta);
    EXPECT_EQ(in_process.humans[i].group_id, 2u);
  }
  // About 4.9 m at 1.05 m/s: after 10 s the walking group has become conversation group 2.
  EXPECT_TRUE(in_process.walking_groups.empty());
  ASSERT_EQ(in_process.groups.size(), 1u);
  EXPECT_EQ(in_process.groups[0].id, 2u);
  EXPECT_EQ(in_process.groups[0].arrangement, model::Arrangement::kVisAVis);
}

}  // namespace
}  // namespace ari_social_sim::engine
