#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/speech_playback.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(SpeechPlayback, StartsWhenTheWorldSaysItAndEndsWhenItStops) {
  SpeechPlayback playback;
  EXPECT_TRUE(playback.done());  // nothing handed over yet
  playback.begin(10, "where is the toilet", 2.0);
  const SpeakerState before{true, "where is the toilet", 1.0, 2};  // an older act, same words
  playback.follow(&before);
  EXPECT_FALSE(playback.done());
  EXPECT_EQ(playback.words_started(), 0u);
  for (size_t word = 0; word < 4; ++word) {
    const SpeakerState saying{true, "where is the toilet", 2.05, word};
    playback.follow(&saying);
    EXPECT_EQ(playback.words_started(), word + 1);
  }
  EXPECT_FALSE(playback.done());
  const SpeakerState silent{false, "", 0.0, 0};
  playback.follow(&silent);
  EXPECT_TRUE(playback.done());
  EXPECT_EQ(playback.words_started(), 4u);
}

TEST(SpeechPlayback, PlayedToItsEndCountsEveryWordEvenMissedStates) {
  SpeechPlayback playback;
  playback.begin(10, "where is the toilet", 2.0);
  const SpeakerState first_word{true, "where is the toilet", 2.05, 0};
  playback.follow(&first_word);
  EXPECT_EQ(playback.words_started(), 1u);
  const SpeakerState silent{false, "", 0.0, 0};  // the states of words 2-4 were missed
  playback.follow(&silent);
  EXPECT_TRUE(playback.done());
  EXPECT_EQ(playback.words_started(), 4u);
}

TEST(SpeechPlayback, AnotherActOrALeavingSpeakerEndsIt) {
  SpeechPlayback playback;
  playback.begin(10, "hello", 0.0);
  const SpeakerState saying{true, "hello", 0.05, 0};
  playback.follow(&saying);
  const SpeakerState other{true, "goodbye", 0.3, 0};  // cut off by another act
  playback.follow(&other);
  EXPECT_TRUE(playback.done());

  playback.begin(11, "hello", 1.0);
  playback.follow(nullptr);  // removed from the world before it started
  EXPECT_TRUE(playback.done());
  EXPECT_EQ(playback.speaker_id(), 11u);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
