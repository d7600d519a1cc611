// The batch tool's bags: the same scenario and seed give a byte-identical file; another seed a
// different one; the topics and types are those of launch/record.launch's live recording.
#include <gtest/gtest.h>
#include <rosbag/view.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "episode_bag/episode_bag.hpp"

namespace ari_social_sim::tools {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

// A randomised group of 2-5 chatting in D6.4's 6 x 6 m room, and nobody else: what changes with the
// seed is the group's size, place and turn, and its members' gaze.
scenario::Scenario random_group_scenario() {
  const std::string text =
      "world: " + kSource +
      "/worlds/room_6x6.yaml\nseed: 1\n"
      "script:\n"
      "  time_limit: 20\n"
      "  random_groups: [{id: 1, first_human_id: 10, size: [2, 5], centre_min: [2.5, 2.5], "
      "centre_max: [3.5, 3.5]}]\n"
      "  start: chat\n"
      "  states:\n"
      "    - name: chat\n"
      "      enter: [{type: say, speaker: 10, act: greet(), text: Hello everybody}]\n"
      "      transitions: [{when: [{type: time_elapsed, seconds: 6}], do: [{type: stop, "
      "success: true}]}]\n";
  return scenario::parse_scenario(core::YamlMap::parse(text, "inline.yaml"), kSource, "chat");
}

std::string run_to_bag(
    const scenario::Scenario& scenario, uint64_t seed, const std::string& name,
    core::PendingFile::Naming naming = core::PendingFile::Naming::unnamed_where_possible) {
  const std::string path = ::testing::TempDir() + name + ".bag";
  {
    static const engine::EpisodeConfig config = engine::EpisodeConfig::load(kSource + "/config");
    engine::Episode episode(scenario, seed, config);
    EpisodeBag bag(path, scenario.name, naming);
    while (!episode.finished()) {
      episode.step();
      bag.record_step(episode);
    }
    bag.finish();
  }
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

TEST(EpisodeBag, SameSeedSameBytesOtherSeedOtherBytes) {
  const scenario::Scenario scenario = random_group_scenario();
  const std::string a = run_to_bag(scenario, 4, "a");
  const std::string b = run_to_bag(scenario, 4, "b");
  const std::string c = run_to_bag(scenario, 5, "c");
  const std::string named =
      run_to_bag(scenario, 4, "named", core::PendingFile::Naming::always_named);
  ASSERT_GT(a.size(), 100000u);  // 120 steps of world state, the map
  EXPECT_TRUE(a == b) << "two runs with seed 4 wrote different bags";
  EXPECT_TRUE(a == named) << "a bag written under its .active name differs from an unnamed one";
  EXPECT_FALSE(a == c) << "seeds 4 and 5 wrote the same bag";
}

TEST(EpisodeBag, CompleteUnderItsNameOrAbsent) {
  namespace fs = std::filesystem;
  const scenario::Scenario scenario = random_group_scenario();
  static const engine::EpisodeConfig config = engine::EpisodeConfig::load(kSource + "/config");
  const std::string done = ::testing::TempDir() + "finished.bag";
  const std::string cut = ::testing::TempDir() + "interrupted.bag";
  fs::remove(done);
  fs::remove(cut);
  {
    engine::Episode episode(scenario, 4, config);
    EpisodeBag finished(done, scenario.name);
    EpisodeBag interrupted(cut, scenario.name);
    for (int step = 0; step < 40; ++step) {  // 2 s of the 6 s chat
      episode.step();
      finished.record_step(episode);
      interrupted.record_step(episode);
    }
    // While written, a bag has no name at all.
    EXPECT_FALSE(fs::exists(done + ".active"));
    EXPECT_FALSE(fs::exists(done));
    finished.finish();
    EXPECT_TRUE(fs::exists(done));
    EXPECT_FALSE(fs::exists(done + ".active"));
  }  // `interrupted` is dropped unfinished, as an interrupted run drops the episode under way
  EXPECT_FALSE(fs::exists(cut));
  EXPECT_FALSE(fs::exists(cut + ".active"));
  rosbag::Bag bag(done, rosbag::bagmode::Read);
  rosbag::View clock(bag, rosbag::TopicQuery("/clock"));
  EXPECT_EQ(clock.size(), 40u);  // one per step
}

TEST(EpisodeBag, TopicsTypesAndCounts) {
  const scenario::Scenario scenario = random_group_scenario();
  run_to_bag(scenario, 4, "topics");
  rosbag::Bag bag(::testing::TempDir() + "topics.bag", rosbag::bagmode::Read);
  rosbag::View view(bag);
  std::map<std::string, std::string> types;
  std::map<std::string, int> counts;
  double first_s = 1e9, last_s = 0.0;
  for (const rosbag::MessageInstance& m : view) {
    types[m.getTopic()] = m.getDataType();
    ++counts[m.getTopic()];
    first_s = std::min(first_s, m.getTime().toSec());
    last_s = std::max(last_s, m.getTime().toSec());
  }
  const std::map<std::string, std::string> expected = {
      {"/clock", "rosgraph_msgs/Clock"},
      {"/humans/bodies/tracked", "ari_social_sim/IdsList"},
      {"/humans/faces/tracked", "ari_social_sim/IdsList"},
      {"/humans/persons/known", "ari_social_sim/IdsList"},
      {"/humans/persons/tracked", "ari_social_sim/IdsList"},
      {"/humans/voices/tracked", "ari_social_sim/IdsList"},
      {"/map", "nav_msgs/OccupancyGrid"},
      {"/scenario/status", "ari_social_sim/ScenarioStatus"},
      {"/sim/world_state", "ari_social_sim/WorldState"},
      {"/tf_static", "tf2_msgs/TFMessage"}};
  // No ARI in this scene: no odometry, no /tf, and perception reports nobody (empty lists).
  EXPECT_EQ(types, expected);
  EXPECT_EQ(counts["/humans/persons/tracked"], 121);  // perception at 20 Hz, below its 30 Hz cap
  // The script stops 6 s after its first step (0.05 s): 121 steps of 0.05 s, one state each.
  EXPECT_EQ(counts["/sim/world_state"], 121);
  EXPECT_EQ(counts["/scenario/status"], 2);  // entering `chat`, finishing
  EXPECT_DOUBLE_EQ(first_s, 0.05);
  EXPECT_NEAR(last_s, 6.05, 1e-9);
}

}  // namespace
}  // namespace ari_social_sim::tools
