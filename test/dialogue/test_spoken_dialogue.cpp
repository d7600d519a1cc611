#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/robot_nlu.hpp"
#include "ari_social_sim/dialogue/spoken_dialogue.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr double kTick = 0.05;  // s, a world step

// A stage on a test clock: every utterance plays at 150 words per minute (0.4 s a word).
class ClockStage : public SpeechStage {
 public:
  double now{0.0};
  std::vector<std::string> voiced;  // `ARI: text` or `<role index>: text`, as started

  double now_s() const override { return now; }
  bool has_listener() const override { return true; }
  void start_human(const Utterance& utterance, size_t human) override {
    voiced.push_back(std::to_string(human) + ": " + utterance.text);
    human_end_ = now + 0.4 * split_words(utterance.text).size();
  }
  bool human_done() override { return now >= human_end_ - 1e-9; }
  void start_robot(const std::string& text) override {
    voiced.push_back("ARI: " + text);
    robot_start_ = now;
    robot_end_ = now + 0.4 * split_words(text).size();
  }
  size_t robot_words_started() override {
    return now < robot_start_ ? 0 : static_cast<size_t>(std::floor((now - robot_start_) / 0.4)) + 1;
  }
  bool robot_done() override { return now >= robot_end_ - 1e-9; }
  uint32_t human_id(size_t human) const override { return 10 + static_cast<uint32_t>(human); }
  uint32_t robot_id() const override { return 1; }

 private:
  double human_end_{-1.0};
  double robot_start_{0.0};
  double robot_end_{-1.0};
};

class SpokenDialogueTest : public ::testing::Test {
 protected:
  SpokenDialogueTest() {
    setup = DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR));
    nlu = std::make_unique<RobotNlu>(*setup->nlg, setup->domain, setup->corpus_or_null());
  }
  // Ticks until `until_s`, gathering the events.
  SpokenDialogueEvents run(SpokenDialogue& dialogue, double until_s) {
    SpokenDialogueEvents all;
    for (; stage.now < until_s - 1e-9; stage.now += kTick) {
      dialogue.tick();
      SpokenDialogueEvents e = dialogue.take_events();
      all.robot_words.insert(all.robot_words.end(), e.robot_words.begin(), e.robot_words.end());
      all.utterances.insert(all.utterances.end(), e.utterances.begin(), e.utterances.end());
      all.outcomes.insert(all.outcomes.end(), e.outcomes.begin(), e.outcomes.end());
      if (e.robot_done) {
        all.robot_done = e.robot_done;
      }
    }
    return all;
  }

  std::unique_ptr<DialogueSetup> setup;
  std::unique_ptr<RobotNlu> nlu;
  ClockStage stage;
  DialogueRunConfig run_config;
};

TEST_F(SpokenDialogueTest, VoiceOnlyPlaysAriAndNobodyElse) {
  run_config.humans = false;
  SpokenDialogue dialogue(*setup, *nlu, run_config, stage);
  EXPECT_EQ(dialogue.request_robot("Hello, I am ARI. Can I help you?", 0.0), "");
  const SpokenDialogueEvents events = run(dialogue, 30.0);
  EXPECT_EQ(stage.voiced, std::vector<std::string>{"ARI: Hello, I am ARI. Can I help you?"});
  // 8 words at 0.4 s: one feedback per word, the last at 7 x 0.4 s with everything said.
  ASSERT_EQ(events.robot_words.size(), 8u);
  EXPECT_EQ(events.robot_words.back().text_said, "Hello, I am ARI. Can I help you?");
  EXPECT_NEAR(events.robot_words.back().since_start_s, 2.8, kTick + 1e-9);  // one tick of play
  ASSERT_TRUE(events.robot_done.has_value());
  EXPECT_TRUE(events.utterances.empty());
  EXPECT_TRUE(events.outcomes.empty());
  EXPECT_FALSE(dialogue.dialogue_active());
}

TEST_F(SpokenDialogueTest, WhenAriSpeaksTheDialogueStartsWithIt) {
  run_config.start = DialogueStart::kRobotSpeaks;
  SpokenDialogue dialogue(*setup, *nlu, run_config, stage);
  // Nobody speaks before ARI does, however long it waits.
  run(dialogue, 20.0);
  EXPECT_TRUE(stage.voiced.empty());
  EXPECT_FALSE(dialogue.dialogue_active());
  dialogue.request_robot("Hello, how can I help you?", 0.0);
  const SpokenDialogueEvents events = run(dialogue, 60.0);
  ASSERT_GE(stage.voiced.size(), 2u);
  EXPECT_EQ(stage.voiced[0], "ARI: Hello, how can I help you?");  // ARI opened it
  ASSERT_FALSE(events.utterances.empty());
  EXPECT_EQ(events.utterances[0].speaker_id, 1u);  // ARI's utterance, then the humans'
  EXPECT_EQ(dialogue.live().env().transcript()[0].speaker, kRobot);
  for (size_t i = 1; i < events.utterances.size(); ++i) {
    const uint32_t id = events.utterances[i].speaker_id;
    EXPECT_TRUE(id == 1 || id == 10 || id == 11) << id;
  }
}

TEST_F(SpokenDialogueTest, RefusesEmptyTextAndNegativeWaits) {
  SpokenDialogue dialogue(*setup, *nlu, run_config, stage);
  EXPECT_NE(dialogue.request_robot("   ", 0.0).find("rawtext.text"), std::string::npos);
  EXPECT_NE(dialogue.request_robot("hello", -1.0).find("wait_before_speaking"), std::string::npos);
}

TEST_F(SpokenDialogueTest, SameSeedSameDialogue) {
  // At once, as dialogue_node's default: the humans may open, ARI answers once.
  std::vector<std::string> voiced[2];
  for (int run_index = 0; run_index < 2; ++run_index) {
    ClockStage fresh;
    stage = fresh;
    SpokenDialogue dialogue(*setup, *nlu, run_config, stage);
    run(dialogue, 10.0);
    dialogue.request_robot("Hello, how can I help you?", 0.0);
    run(dialogue, 40.0);
    voiced[run_index] = stage.voiced;
  }
  EXPECT_FALSE(voiced[0].empty());
  EXPECT_EQ(voiced[0], voiced[1]);
}

// /sim/reset sends the world's clock back: the dialogue under way ends there, truncated, and the
// next one starts a dialogue_pause later on the new clock, not when the old clock would have
// come round again (at 20 minutes into a run, 20 minutes of silence).
TEST_F(SpokenDialogueTest, AClockThatGoesBackEndsTheDialogueAndStartsTheNextAPauseLater) {
  SpokenDialogue dialogue(*setup, *nlu, run_config, stage);
  run(dialogue, 600.0);
  ASSERT_TRUE(dialogue.dialogue_active()) << "no dialogue under way at 600 s";
  stage.now = 1.0;  // the reset
  const SpokenDialogueEvents after = run(dialogue, 30.0);
  ASSERT_FALSE(after.outcomes.empty());
  const OutcomeEvent& cut_off = after.outcomes[0];
  EXPECT_NEAR(cut_off.stamp_s, 1.0, 1e-9);
  EXPECT_TRUE(cut_off.truncated);
  EXPECT_FALSE(cut_off.success);
  ASSERT_FALSE(after.utterances.empty()) << "silence after the reset";
  const UtteranceEvent& first = after.utterances[0];
  EXPECT_EQ(first.dialogue, cut_off.dialogue + 1);
  EXPECT_GE(first.stamp_s, 1.0 + run_config.dialogue_pause_s - 1e-9);
  EXPECT_LT(first.stamp_s, 1.0 + run_config.dialogue_pause_s + 5.0);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
