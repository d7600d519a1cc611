#include <gtest/gtest.h>

#include <fstream>

#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/config_writer.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "expect_config_error.hpp"
#include "refusal_text.hpp"

namespace ari_social_sim::world {
namespace {

const std::string kWorlds = std::string(ARI_SOURCE_DIR) + "/worlds/";

std::string write_scene(const std::string& body) {
  const std::string path = ::testing::TempDir() + "scene_under_test.yaml";
  std::ofstream(path) << "world: " << kWorlds << "room_6x6.yaml\nseed: 3\n" << body;
  return path;
}

// Loading and building the scene fails with a message naming the file and every fragment.
void expect_rejected(const std::string& body, const std::vector<std::string>& fragments) {
  const std::string path = write_scene(body);
  test::expect_config_error([&] { build_simulation(load_scene_file(path), SimulationConfig{}); },
                            path, fragments);
}

TEST(Scene, BuildsHumansGroupsAndAri) {
  const Scene scene = load_scene_file(write_scene(
      "ari: {position: [1, 1], orientation: 0.5}\n"
      "humans:\n"
      "  - {id: 10, position: [3, 3], age: 70, gender: female, mask: true, emotion: angry}\n"
      "  - {id: 11, position: [4, 3], gaze: {mean_duration: 2, targets: [{id: 10, probability: "
      "1}]}}\n"
      "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3.5]}\n"));
  EXPECT_EQ(scene.seed, 3u);
  const auto simulation = build_simulation(scene, SimulationConfig{});
  ASSERT_NE(simulation->ari(), nullptr);
  EXPECT_DOUBLE_EQ(simulation->ari()->pose().theta, 0.5);
  const Human& human = *simulation->find_human(10);
  EXPECT_EQ(human.spec().gender, model::Gender::kFemale);
  EXPECT_TRUE(human.spec().mask);
  EXPECT_EQ(human.spec().emotion, model::Emotion::kAngry);
  EXPECT_EQ(human.group_id(), 1u);
  EXPECT_EQ(simulation->config().seed, 3u);
}

TEST(Scene, OverlappingSpawnPositionsNameBothHumans) {
  expect_rejected("humans:\n  - {id: 10, position: [3, 3]}\n  - {id: 11, position: [3.1, 3]}\n",
                  {"humans[1]", "human 11", "overlap", "human 10"});
}

TEST(Scene, SpawnInsideAWallIsRejected) {
  expect_rejected("humans:\n  - {id: 10, position: [0.05, 3]}\n",
                  {"humans[0]", "overlap", "wall or furniture"});
}

TEST(Scene, UnknownGenderAndMissingPositionAreNamed) {
  expect_rejected("humans:\n  - {id: 10, position: [3, 3], gender: robot}\n",
                  {"humans[0].gender", "female, male or non-identified", "robot"});
  expect_rejected("humans:\n  - {id: 10}\n", {"humans[0].position", "required"});
}

TEST(Scene, PostureIsReadAndABadOneIsNamed) {
  const auto simulation = build_simulation(
      load_scene_file(write_scene("humans:\n  - {id: 10, position: [3, 3], posture: sitting}\n"
                                  "  - {id: 11, position: [4, 3]}\n")),
      SimulationConfig{});
  EXPECT_EQ(simulation->find_human(10)->posture().posture, Posture::kSitting);
  EXPECT_DOUBLE_EQ(simulation->find_human(10)->posture().seated_fraction(), 1.0);
  EXPECT_EQ(simulation->find_human(11)->posture().posture, Posture::kStanding);
  expect_rejected("humans:\n  - {id: 10, position: [3, 3], posture: kneeling}\n",
                  {"humans[0].posture", "standing or sitting", "kneeling"});
}

TEST(Scene, GroupConversationParametersAreCheckedAndCanSwitchItOff) {
  const std::string humans =
      "humans:\n  - {id: 10, position: [3, 3]}\n  - {id: 11, position: [4, 3]}\n";
  expect_rejected(humans +
                      "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3.5], "
                      "conversation: {lapse_mean: -1}}\n",
                  {"groups[0].conversation.lapse_mean", "(0, 60]", "-1"});
  expect_rejected(humans +
                      "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3.5], "
                      "conversation: {enabled: maybe}}\n",
                  {"groups[0].conversation.enabled", "maybe"});
  const auto quiet = build_simulation(
      load_scene_file(write_scene(humans +
                                  "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3.5], "
                                  "conversation: {enabled: false}}\n")),
      SimulationConfig{});
  EXPECT_EQ(quiet->find_conversation(1), nullptr);
  const auto talking = build_simulation(
      load_scene_file(
          write_scene(humans + "groups:\n  - {id: 1, members: [10, 11], centre: [3.5, 3.5]}\n")),
      SimulationConfig{});
  ASSERT_NE(talking->find_conversation(1), nullptr);
  EXPECT_TRUE(talking->find_conversation(1)->spec().enabled);
}

TEST(Scene, GazeProbabilitiesMustSumToOneAndNameObjects) {
  expect_rejected(
      "humans:\n  - {id: 10, position: [3, 3], gaze: {mean_duration: 2, targets: "
      "[{id: 11, probability: 0.5}]}}\n",
      {"humans[0].gaze.targets", "that sum to 1"});
  expect_rejected(
      "humans:\n  - {id: 10, position: [3, 3], gaze: {mean_duration: 2, targets: "
      "[{id: 99, probability: 1.0}]}}\n",
      {"humans[0].gaze.targets", "99"});
}

TEST(Scene, GroupOfUnknownHumanIsRejected) {
  expect_rejected(
      "humans:\n  - {id: 10, position: [3, 3]}\ngroups:\n  - {id: 1, members: [10, 12], centre: "
      "[3, 3]}\n",
      {"groups[0]", "no human with id 12"});
}

TEST(Scene, MissingWorldFileIsNamed) {
  const std::string path = ::testing::TempDir() + "scene_bad_world.yaml";
  std::ofstream(path) << "world: nowhere.yaml\nseed: 1\n";
  try {
    load_scene_file(path);
    FAIL();
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": world"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nowhere.yaml"), std::string::npos) << e.what();
  }
}

TEST(Scene, GoalsAndCentresOffTheFloorAreRefused) {
  // room_6x6's floor spans [-0.2, 6.2] on both axes.
  expect_rejected("humans:\n  - {id: 10, position: [3, 3], goal: {position: [3, 40]}}\n",
                  {"humans[0]", "spawn_human: goal.y",
                   "expected a finite number inside the world [-0.2, 6.2], got 40"});
  expect_rejected(
      "humans:\n  - {id: 10, position: [3, 3]}\ngroups:\n  - {id: 1, members: [10], centre: "
      "[-9, 3]}\n",
      {"groups[0]", "create_group: centre.x", "got -9"});
  expect_rejected(
      "humans:\n  - {id: 10, position: [3, 3], gaze: {mean_duration: 1e6, "
      "directions: {distribution: normal, mean: 0, stddev: 0.3}}}\n",
      {"humans[0].gaze.mean_duration", "(0, 86400]", "1e6"});
  expect_rejected("ari: {position: [1e9, 1]}\n",
                  {"ari", "pose.x", "inside the world [-0.2, 6.2]", "1e+09"});
}

TEST(Scene, CountsHaveDocumentedMaxima) {
  std::string humans = "humans:\n";
  for (int i = 0; i <= 1000; ++i) {
    humans += "  - {id: " + std::to_string(10 + i) + ", position: [3, 3]}\n";
  }
  expect_rejected(humans, {": humans", "at most 1000 humans", "1001"});
  std::string members = "[10";
  for (int i = 11; i <= 60; ++i) {
    members += ", " + std::to_string(i);
  }
  expect_rejected("groups:\n  - {id: 1, members: " + members + "], centre: [3, 3]}\n",
                  {"groups[0]", "members", "at most 50 humans", "got 51"});
  std::string targets = "[{id: 1, probability: 1}";
  for (int i = 0; i < 50; ++i) {
    targets += ", {id: 1, probability: 0}";
  }
  expect_rejected("humans:\n  - {id: 10, position: [3, 3], gaze: {mean_duration: 1, targets: " +
                      targets + "]}}\n",
                  {"humans[0].gaze.targets", "at most 50 targets", "51"});
}

TEST(Scene, DirectoriesAndOversizedScenesAreRefusedBeforeReading) {
  // A directory used to abort world_node with an uncaught exception (exit 134).
  test::expect_config_error([] { load_scene_file(kWorlds); }, kWorlds,
                            {"expected a YAML file, got a directory"});
  // A 50 MB scene used to take 3.5 GB and 24 s before its error; 2 MB is refused unread.
  const std::string path = write_scene("# " + std::string(2 * 1024 * 1024, 'x') + "\n");
  test::expect_config_error([&] { load_scene_file(path); }, path,
                            {"expected a YAML file of at most 1048576 bytes"});
  // The scene's world file gets the same checks, named through the scene's `world` field.
  const std::string scene = ::testing::TempDir() + "scene_world_is_a_directory.yaml";
  std::ofstream(scene) << "world: " << kWorlds << "\nseed: 1\n";
  test::expect_config_error([&] { load_scene_file(scene); }, scene + ": world",
                            {"got a directory"});
}

// The message a spec built in code is refused with, or "" when its validate() accepts it.
template <class Spec>
std::string refusal(const Spec& spec) {
  return test::refusal_text([&] { spec.validate(); });
}

TEST(SceneEntries, SpecsBuiltInCodeAreCheckedAgainstTheBoundsFilesAreReadWith) {
  HumanSpec human;
  human.id = 10;
  human.motion.max_speed_mps = -1.0;
  EXPECT_EQ(refusal(human), "motion.max_speed: expected a number > 0, got -1");
  human.motion = HumanMotionParams{};
  human.gaze = GazeModel{};
  human.gaze->directions = GazeDirections{};
  human.gaze->directions->low_rad = 1.0;
  EXPECT_EQ(refusal(human), "gaze.directions.high: expected a number >= low (1), got 0.5");
  human.gaze->directions->low_rad = -0.5;
  human.gaze->targets.push_back({11, 1.0});
  EXPECT_EQ(refusal(human),
            "gaze.targets: expected either a list of targets or directions (exactly one of "
            "them), got both");

  GroupSpec group;
  group.id = 1;
  group.members = {10, 11, 10};
  EXPECT_EQ(refusal(group), "members: expected each human once, got a human listed twice");
  group.members = {10, 11};
  group.spacing_factor = 1.6;
  EXPECT_EQ(refusal(group), "spacing_factor: expected a number below 1.6, got 1.6");

  AriSpec ari;
  ari.head_pan_rad = 1.4;
  EXPECT_EQ(refusal(ari), "head_pan: expected a number in [-1.309, 1.309], got 1.4");
  ari.head_pan_rad = 0.0;
  ari.limits.max_linear_mps = 0.0;
  EXPECT_EQ(refusal(ari), "limits: max_linear: expected a number > 0, got 0");
  ari.limits = model::AriLimits{};
  ari.footprint.front_x_m = -0.7;
  EXPECT_EQ(refusal(ari),
            "footprint: front_x: expected a number at least 0.005 m above rear_x (-0.6), got -0.7");
}

TEST(SceneEntries, AnEntryWrittenFromItsFieldsReadsBackTheSame) {
  HumanSpec human;
  human.id = 12;
  human.pose = {{2.5, 1.25}, 0.75};
  human.age_years = 67.0;
  human.gender = model::Gender::kMale;
  human.emotion = model::Emotion::kDisturbed;
  human.motion.personal_distance_m = 0.65;
  human.goal = core::Pose2{{4.0, 4.5}, -1.0};
  human.gaze = GazeModel{{{10, 0.25}, {1, 0.75}}, std::nullopt, 2.5};
  const HumanSpec read =
      core::read_fields<HumanSpec>(core::YamlMap::parse(core::write_fields(human), "written"));
  EXPECT_EQ(read.id, 12u);
  EXPECT_EQ(read.pose.position, human.pose.position);
  EXPECT_EQ(read.pose.theta, 0.75);
  EXPECT_EQ(read.age_years, 67.0);
  EXPECT_EQ(read.gender, model::Gender::kMale);
  EXPECT_EQ(read.emotion, model::Emotion::kDisturbed);
  EXPECT_EQ(read.motion.personal_distance_m, 0.65);
  ASSERT_TRUE(read.goal.has_value());
  EXPECT_EQ(read.goal->position, human.goal->position);
  ASSERT_TRUE(read.gaze.has_value());
  ASSERT_EQ(read.gaze->targets.size(), 2u);
  EXPECT_EQ(read.gaze->targets[1].id, 1u);
  EXPECT_EQ(read.gaze->targets[1].probability, 0.75);
  EXPECT_EQ(read.gaze->mean_duration_s, 2.5);
  EXPECT_FALSE(read.gaze->directions.has_value());
}

TEST(Scene, ShippedScenesBuild) {
  for (const char* name : {"waiting_room", "flat_group_formation", "gathering"}) {
    const Scene scene = load_scene_file(std::string(ARI_SOURCE_DIR) + "/scenes/" + name + ".yaml");
    const auto simulation = build_simulation(scene, SimulationConfig{});
    EXPECT_GE(simulation->humans().size(), 3u) << name;
    EXPECT_GE(simulation->groups().size(), 1u) << name;
  }
}

}  // namespace
}  // namespace ari_social_sim::world
