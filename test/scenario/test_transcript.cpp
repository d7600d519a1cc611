#include <gtest/gtest.h>

#include "ari_social_sim/scenario/transcript.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

// The real world plays the words; the transcript follows it step by step.
TEST(Transcript, FollowsTheWorldsSpeechWithStartAndEndTimes) {
  const world::Scene scene = world::load_scene_file(kSource + "/scenarios/group_discussion.yaml");
  auto simulation = world::build_simulation(scene, world::SimulationConfig{});
  Transcript transcript;
  // 4 words at 150 words per minute: 1.6 s, ending at the first step at or after it.
  simulation->say(simulation->ari()->id(), "QUESTION:HELP", "Can I help you?");
  std::vector<size_t> finished_at;
  for (int step = 0; step < 80; ++step) {
    simulation->step();
    if (step == 10) {
      simulation->say(11, "QUESTION:TIME", "What is the time?");
    }
    for (size_t line : transcript.observe(world::WorldSnapshot::of(*simulation))) {
      finished_at.push_back(line);
    }
  }
  const auto& lines = transcript.lines();
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].speaker_name, "ARI");
  EXPECT_EQ(lines[0].act, "QUESTION:HELP");
  EXPECT_DOUBLE_EQ(lines[0].start_s, 0.0);
  EXPECT_NEAR(lines[0].end_s, 1.6, 0.05 + 1e-9);
  EXPECT_EQ(lines[1].speaker_name, "Irene");
  EXPECT_EQ(lines[1].text, "What is the time?");
  EXPECT_NEAR(lines[1].start_s, 0.55, 1e-9);  // said after step 11
  EXPECT_NEAR(lines[1].end_s - lines[1].start_s, 1.6, 0.05 + 1e-9);
  EXPECT_EQ(finished_at, (std::vector<size_t>{0, 1}));
}

TEST(Transcript, ANewActCutsOffTheOneBeforeAndALeavingSpeakerStops) {
  world::WorldSnapshot snapshot;
  world::HumanSnapshot human;
  human.id = 10;
  human.speech = {"A", "one two three", "one", 0, true, 1.0, "", ""};
  snapshot.time_s = 1.0;
  snapshot.humans = {human};
  Transcript transcript;
  EXPECT_TRUE(transcript.observe(snapshot).empty());
  snapshot.time_s = 1.5;
  snapshot.humans[0].speech = {"B", "four", "four", 0, true, 1.5, "A", "one two three"};
  EXPECT_EQ(transcript.observe(snapshot), std::vector<size_t>{0});
  snapshot.time_s = 1.7;
  snapshot.humans.clear();
  EXPECT_EQ(transcript.observe(snapshot), std::vector<size_t>{1});
  ASSERT_EQ(transcript.lines().size(), 2u);
  EXPECT_DOUBLE_EQ(transcript.lines()[0].end_s, 1.5);
  EXPECT_DOUBLE_EQ(transcript.lines()[1].end_s, 1.7);
  EXPECT_EQ(transcript.lines()[1].speaker_name, "human 10");
}

}  // namespace
}  // namespace ari_social_sim::scenario
