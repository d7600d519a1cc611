#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/turn_timing.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(TurnTiming, DurationAtSpeechRate) {
  const TurnTiming timing(TurnTimingConfig{});
  EXPECT_DOUBLE_EQ(timing.duration("where is the cafeteria please"), 2.0);  // 5 words x 0.4 s
  EXPECT_DOUBLE_EQ(timing.duration("Ok."), 0.4);                            // 1 word, the minimum
}

TEST(TurnTiming, GapsAreClippedNormal) {
  const TurnTiming timing(TurnTimingConfig{});
  core::Rng rng(2);
  double sum = 0;
  int zero = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double gap = timing.next_start(10.0, rng) - 10.0;
    ASSERT_GE(gap, 0.0);
    sum += gap;
    zero += gap == 0.0 ? 1 : 0;
  }
  // N(0.2, 0.2) clipped at 0: P(gap = 0) = Phi(-1) = 0.159; mean = 0.2 Phi(1) + 0.2 phi(1)
  // = 0.2 x 0.841 + 0.2 x 0.242 = 0.217.
  EXPECT_NEAR(zero / double(n), 0.159, 0.01);
  EXPECT_NEAR(sum / n, 0.217, 0.005);
}

TEST(TurnTiming, RejectsZeroSpeechRate) {
  TurnTimingConfig config;
  config.seconds_per_word = 0.0;
  testing::expect_config_error([&] { TurnTiming{config}; },
                               {"TurnTimingConfig: seconds_per_word", "> 0", "got 0"});
}

}  // namespace
}  // namespace ari_social_sim::dialogue
