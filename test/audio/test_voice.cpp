#include <gtest/gtest.h>

#include "ari_social_sim/audio/voice.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::audio {
namespace {

double mean_pitch(model::Gender gender, double age_years) {
  double sum = 0.0;
  for (uint64_t id = 1; id <= 100; ++id) {
    sum += voice_for(7, id, gender, age_years).pitch;
  }
  return sum / 100.0;
}

TEST(Voice, TheSameSeedAndIdGiveTheSameVoiceAndOtherIdsOthers) {
  EXPECT_EQ(voice_for(7, 3, model::Gender::kFemale, 40.0).key(),
            voice_for(7, 3, model::Gender::kFemale, 40.0).key());
  int different = 0;
  for (uint64_t id = 1; id <= 20; ++id) {
    different += voice_for(7, id, model::Gender::kFemale, 40.0) ==
                         voice_for(8, id, model::Gender::kFemale, 40.0)
                     ? 0
                     : 1;
  }
  EXPECT_GE(different, 19);
}

// Women's voices are higher than men's, and women's fall with age.
TEST(Voice, PitchFollowsGenderAndAge) {
  const double women = mean_pitch(model::Gender::kFemale, 35.0);
  const double men = mean_pitch(model::Gender::kMale, 35.0);
  std::printf("mean espeak pitch: women %.1f, men %.1f, women at 80 %.1f\n", women, men,
              mean_pitch(model::Gender::kFemale, 80.0));
  EXPECT_GT(women - men, 15.0);
  EXPECT_LT(mean_pitch(model::Gender::kFemale, 80.0), women - 10.0);
  EXPECT_EQ(voice_for(7, 3, model::Gender::kMale, 30.0).variant[0], 'm');
  EXPECT_EQ(voice_for(7, 3, model::Gender::kFemale, 30.0).variant[0], 'f');
}

TEST(Voice, AVoiceEspeakCannotSpeakIsRefusedByField) {
  Voice voice = ari_voice();
  EXPECT_NO_THROW(check_voice(voice));
  voice.variant = "robot9";
  EXPECT_THROW(
      {
        try {
          check_voice(voice);
        } catch (const core::RequestError& e) {
          EXPECT_NE(std::string(e.what()).find("variant"), std::string::npos) << e.what();
          throw;
        }
      },
      core::RequestError);
  voice = ari_voice();
  voice.rate_wpm = 20;
  EXPECT_THROW(check_voice(voice), core::RequestError);
}

}  // namespace
}  // namespace ari_social_sim::audio
