#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/dialogue/live_dialogue.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

constexpr double kTick = 0.01;  // s, the test clock's resolution

/// One played human utterance: transcript index and when it started and ended on the clock.
struct Played {
  int index;
  double start_s;
  double end_s;
};

class LiveDialogueTest : public ::testing::Test {
 protected:
  explicit LiveDialogueTest(unsigned max_turns = 40) {
    DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
    config.reward.max_turns = max_turns;
    setup_ = DialogueSetup::create(config);
    nlu_ = std::make_unique<RobotNlu>(*setup_->nlg, setup_->domain, setup_->corpus_or_null());
    live_ = std::make_unique<LiveDialogue>(*setup_, *nlu_, LiveDialogueConfig{});
  }

  /// Runs the clock from `now_s` until `until_s`, playing each due human utterance for the
  /// duration the turn timing gives it. Returns what was played.
  std::vector<Played> run(double& now_s, double until_s) {
    std::vector<Played> played;
    double playing_until = -1.0;
    for (; now_s < until_s - 1e-9; now_s += kTick) {
      if (playing_until >= 0.0 && now_s >= playing_until - 1e-9) {
        live_->human_finished(now_s);
        played.back().end_s = now_s;
        playing_until = -1.0;
      }
      const int due = live_->next_due(now_s);
      if (due >= 0) {
        const Utterance& u = live_->env().transcript()[due];
        played.push_back({due, now_s, 0.0});
        playing_until = now_s + setup_->timing->duration(u.text);
      }
    }
    return played;
  }

  /// The first seed from 0 whose dialogue the humans open (robot_opens = 0.72 in the fitted model).
  uint64_t seed_where_humans_open() {
    for (uint64_t seed = 0;; ++seed) {
      live_->start(seed, 0.0);
      if (!live_->robot_may_speak()) {
        return seed;
      }
    }
  }

  const Utterance& utterance(int index) const { return live_->env().transcript()[index]; }

  std::unique_ptr<DialogueSetup> setup_;
  std::unique_ptr<RobotNlu> nlu_;
  std::unique_ptr<LiveDialogue> live_;
};

TEST_F(LiveDialogueTest, HumansKeepTheDrawnGapsOrWaitOutTheSilence) {
  const uint64_t seed = seed_where_humans_open();
  double now = 100.0;
  live_->start(seed, now);
  const std::vector<Played> played = run(now, 160.0);
  ASSERT_GE(played.size(), 5u);
  // The first starts at 100 s + its start on the dialogue clock (the gap after the start).
  EXPECT_NEAR(played[0].start_s, 100.0 + utterance(played[0].index).start_s, kTick + 1e-9);
  // Each next one starts after the real end of the previous plus either the gap the turn timing
  // drew for it (same turn) or, when ARI said nothing, robot_silence_s = 3 s (a silent step).
  int silences = 0;
  for (size_t i = 1; i < played.size(); ++i) {
    const Utterance& u = utterance(played[i].index);
    const double drawn_gap = u.start_s - utterance(played[i].index - 1).end_s;
    const double pause = played[i].start_s - played[i - 1].end_s;
    if (std::abs(pause - 3.0) <= kTick + 1e-9) {
      ++silences;
    } else {
      EXPECT_NEAR(pause, drawn_gap, kTick + 1e-9) << i;
    }
  }
  // Every robot turn so far was a silence (the clock stops before the last may be due).
  const int robot_turns = live_->last_result().info.robot_turns;
  EXPECT_GE(silences, 2);
  EXPECT_EQ(silences, robot_turns);
}

TEST_F(LiveDialogueTest, RobotWaitsForTheFloorAndHumansAnswerIt) {
  const uint64_t seed = seed_where_humans_open();
  double now = 0.0;
  live_->start(seed, now);
  live_->request_floor();
  // The opening plays out; ARI may speak once it is over, and the silence timer is held.
  run(now, 30.0);
  EXPECT_TRUE(live_->robot_may_speak());
  const size_t before = live_->env().transcript().size();
  const int robot = live_->robot_finished("Hello. My name is ARI. How can I help you?", now);
  ASSERT_EQ(robot, static_cast<int>(before));
  EXPECT_EQ(acts_to_string(utterance(robot).acts), "greet(); inform(ari(name)); offer-help()");
  EXPECT_EQ(utterance(robot).text, "Hello. My name is ARI. How can I help you?");
  EXPECT_EQ(live_->last_result().info.robot_turns, 1);
  // The reply comes after ARI's end plus the drawn gap.
  const double robot_end = now;
  const std::vector<Played> reply = run(now, now + 10.0);
  ASSERT_FALSE(reply.empty());
  EXPECT_EQ(reply[0].index, robot + 1);
  EXPECT_NEAR(reply[0].start_s - robot_end, utterance(robot + 1).start_s - utterance(robot).end_s,
              kTick + 1e-9);
}

TEST_F(LiveDialogueTest, SameSeedSameTimeline) {
  std::vector<std::pair<std::string, double>> first;
  for (int run_index = 0; run_index < 2; ++run_index) {
    live_ = std::make_unique<LiveDialogue>(*setup_, *nlu_, LiveDialogueConfig{});
    double now = 0.0;
    live_->start(11, now);
    std::vector<std::pair<std::string, double>> timeline;
    for (const Played& p : run(now, 40.0)) {
      timeline.emplace_back(utterance(p.index).text, p.start_s);
    }
    if (run_index == 0) {
      first = timeline;
    } else {
      EXPECT_EQ(timeline, first);
    }
  }
  EXPECT_GE(first.size(), 3u);
}

class ShortLiveDialogueTest : public LiveDialogueTest {
 protected:
  ShortLiveDialogueTest() : LiveDialogueTest(3) {}
};

TEST_F(ShortLiveDialogueTest, EndsAtTheTurnCapOnceEverythingIsPlayed) {
  double now = 0.0;
  live_->start(5, now);
  run(now, 120.0);
  // A silent robot: 3 silent steps, then truncation; -3 turns and -40 for failure.
  EXPECT_TRUE(live_->over());
  EXPECT_TRUE(live_->last_result().truncated);
  EXPECT_EQ(live_->last_result().info.robot_turns, 3);
  EXPECT_DOUBLE_EQ(live_->total_reward(), -43.0);
  // Once over, ARI's words change nothing.
  EXPECT_EQ(live_->robot_finished("Hello.", now), -1);
}

TEST(LiveDialogueConfigTest, SilenceMustBePositive) {
  LiveDialogueConfig config;
  config.robot_silence_s = 0.0;
  testing::expect_config_error([&] { config.validate(); }, {"robot_silence", "> 0"});
}

}  // namespace
}  // namespace ari_social_sim::dialogue
