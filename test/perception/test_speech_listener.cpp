#include <gtest/gtest.h>

#include <cstdio>
#include <tuple>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/speech_listener.hpp"
#include "perception_scenes.hpp"

namespace ari_social_sim::perception {
namespace {

using test::human_at;
using test::snapshot_with_ari;
using test::speaking;

const std::string kContent = "where is the radiology room";

class SpeechListenerTest : public ::testing::Test {
 protected:
  void make(const PerceptionConfig& config) {
    config_ = config;
    ids_ = std::make_unique<TransientIds>(core::Rng(1));
    listener_ = std::make_unique<SpeechListener>(config_, *ids_, core::Rng(4));
  }
  std::vector<PerceivedVoice> hear(const world::WorldSnapshot& snapshot,
                                   const model::OccupancyGrid* grid = nullptr) {
    std::vector<PerceivedVoice> voices;
    listener_->update(snapshot, AriSensors::of(*snapshot.ari, config_), grid, 50, voices);
    return voices;
  }

  PerceptionConfig config_;
  std::unique_ptr<TransientIds> ids_;
  std::unique_ptr<SpeechListener> listener_;
};

TEST_F(SpeechListenerTest, AnUtteranceInRangeArrivesWordByWordThenFinal) {
  make(test::config_without_errors());
  world::HumanSnapshot human = human_at(10, 2.0, 1.0, 0.0);
  std::vector<std::string> incrementals;
  std::string final_text;
  std::string voice_id;
  for (uint32_t word = 0; word < 5; ++word) {
    speaking(human, kContent, 0.0, word);
    world::WorldSnapshot snapshot = snapshot_with_ari(0.4 * word);
    snapshot.humans = {human};
    const std::vector<PerceivedVoice> voices = hear(snapshot);
    ASSERT_EQ(voices.size(), 1u);
    EXPECT_TRUE(voices[0].is_speaking);
    EXPECT_EQ(voices[0].human, 10u);
    voice_id = voices[0].voice_id;
    for (const SpeechResult& result : voices[0].speech) {
      EXPECT_TRUE(result.final_text.empty());
      incrementals.push_back(result.incremental);
    }
  }
  human.speech = {};
  world::WorldSnapshot snapshot = snapshot_with_ari(2.0);
  snapshot.humans = {human};
  const std::vector<PerceivedVoice> voices = hear(snapshot);
  ASSERT_EQ(voices.size(), 1u);
  EXPECT_FALSE(voices[0].is_speaking);
  EXPECT_EQ(voices[0].voice_id, voice_id);
  ASSERT_EQ(voices[0].speech.size(), 1u);
  EXPECT_EQ(voices[0].speech[0].final_text, kContent);
  EXPECT_TRUE(voices[0].speech[0].incremental.empty());
  EXPECT_DOUBLE_EQ(voices[0].speech[0].confidence, 1.0);
  EXPECT_EQ(voices[0].transcript, kContent);
  EXPECT_EQ(incrementals, (std::vector<std::string>{"where", "where is", "where is the",
                                                    "where is the radiology", kContent}));
  // The voice stays tracked for voice_timeout (2 s) after its last word, then goes.
  snapshot.time_s = 3.9;
  EXPECT_EQ(hear(snapshot).size(), 1u);
  snapshot.time_s = 4.1;
  EXPECT_TRUE(hear(snapshot).empty());
}

TEST_F(SpeechListenerTest, NothingArrivesThroughAWallOrBeyondRange) {
  make(test::config_without_errors());
  const model::OccupancyGrid grid = test::map_with_wall({2.0, -1.0}, {2.0, 1.0});
  world::HumanSnapshot behind_wall = human_at(10, 3.0, 0.0, 0.0);
  world::HumanSnapshot far_away = human_at(11, -1.0, 5.2, 0.0);  // 5.2 m from the microphone
  for (uint32_t word = 0; word < 5; ++word) {
    speaking(behind_wall, kContent, 0.0, word);
    speaking(far_away, kContent, 0.0, word);
    world::WorldSnapshot snapshot = snapshot_with_ari(0.4 * word);
    snapshot.humans = {behind_wall, far_away};
    EXPECT_TRUE(hear(snapshot, &grid).empty());
  }
}

TEST_F(SpeechListenerTest, ASeatedSpeakerIsHeardOverTheChairUnderThemAStandingOneIsNot) {
  // A chair's front, 0.1 m thick over x = 2.70..2.80, and a speaker at x = 3.05, ARI facing them
  // from the origin. Standing: the line to their centre crosses it. Seated: the map is read up
  // to 3.05 - 2 x 0.2 = 2.65 m, short of it. Seated behind a wall 0.75 m away, still not heard.
  const model::OccupancyGrid chair = test::map_with_wall({2.75, -1.0}, {2.75, 1.0});
  const model::OccupancyGrid wall = test::map_with_wall({2.3, -1.0}, {2.3, 1.0});
  for (const auto& [posture, grid, heard] : {std::tuple{world::Posture::kStanding, &chair, false},
                                             std::tuple{world::Posture::kSitting, &chair, true},
                                             std::tuple{world::Posture::kSitting, &wall, false}}) {
    make(test::config_without_errors());
    world::HumanSnapshot speaker = human_at(10, 3.05, 0.0, core::kPi);
    speaker.posture = {posture, 1.0};
    size_t voices = 0;
    for (uint32_t word = 0; word < 5; ++word) {
      speaking(speaker, kContent, 0.0, word);
      world::WorldSnapshot snapshot = snapshot_with_ari(0.4 * word);
      snapshot.humans = {speaker};
      voices += hear(snapshot, grid).size();
    }
    EXPECT_EQ(voices > 0, heard) << world::posture_name(posture);
  }
}

TEST_F(SpeechListenerTest, WordsBeforeComingInRangeAreLost) {
  make(test::config_without_errors());
  world::HumanSnapshot human = human_at(10, 2.0, 0.0, 0.0);
  speaking(human, kContent, 0.0, 2);
  world::WorldSnapshot snapshot = snapshot_with_ari(0.8);
  snapshot.humans = {human};
  const std::vector<PerceivedVoice> voices = hear(snapshot);
  ASSERT_EQ(voices.at(0).speech.size(), 1u);
  EXPECT_EQ(voices[0].speech[0].incremental, "the");
}

// Must-show 3: the share of utterances attributed to another audible person's voice is within
// 10 % (relative) of misattribution_rate.
TEST_F(SpeechListenerTest, MeasuredMisattributionRateMatchesTheConfiguredOne) {
  PerceptionConfig config = test::config_without_errors();
  config.speech_errors.misattribution_rate = 0.2;
  make(config);
  world::HumanSnapshot speaker = human_at(10, 2.0, 0.0, 0.0);
  const world::HumanSnapshot listener = human_at(11, 2.0, 1.0, 0.0);
  const int utterances = 10000;
  int misattributed = 0;
  for (int i = 0; i < utterances; ++i) {
    // A one-word act per frame, then a silent frame that ends it.
    speaking(speaker, "hello", 2.0 * i, 0);
    world::WorldSnapshot snapshot = snapshot_with_ari(2.0 * i);
    snapshot.humans = {speaker, listener};
    for (const PerceivedVoice& voice : hear(snapshot)) {
      misattributed += !voice.speech.empty() && voice.human == 11 ? 1 : 0;
    }
    speaker.speech = {};
    snapshot.time_s += 1.0;
    snapshot.humans = {speaker, listener};
    hear(snapshot);
  }
  const double rate = static_cast<double>(misattributed) / utterances;
  EXPECT_NEAR(rate, 0.2, 0.02);
  std::printf("[ measured ] speaker misattribution %.4f (configured 0.20)\n", rate);
}

}  // namespace
}  // namespace ari_social_sim::perception
