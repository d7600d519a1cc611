#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/audio/voice_tracks.hpp"

namespace ari_social_sim::audio {
namespace {

double degrees(double d) {
  return d * M_PI / 180.0;
}

TEST(VoiceTracks, AVoiceIsWhereItWasLastHeardWithinTheSeparation) {
  VoiceTracks tracks(degrees(20.0));
  EXPECT_EQ(tracks.voice_from(degrees(30.0)), "voice1");
  EXPECT_EQ(tracks.voice_from(degrees(-100.0)), "voice2");
  EXPECT_EQ(tracks.voice_from(degrees(45.0)), "voice1");  // 15 degrees on: the same person
  EXPECT_EQ(tracks.voice_from(degrees(64.0)), "voice1");  // 19 from where voice1 was last
  EXPECT_EQ(tracks.voice_from(degrees(10.0)), "voice3");  // 54 from voice1 now
  // Across the +-180 degree seam: 175 and -178 degrees are 7 apart.
  EXPECT_EQ(tracks.voice_from(degrees(175.0)), "voice4");
  EXPECT_EQ(tracks.voice_from(degrees(-178.0)), "voice4");
  // Between two voices, the nearer.
  EXPECT_EQ(tracks.voice_from(degrees(-92.0)), "voice2");
  EXPECT_EQ(tracks.ids(), (std::vector<std::string>{"voice1", "voice2", "voice3", "voice4"}));
}

}  // namespace
}  // namespace ari_social_sim::audio
