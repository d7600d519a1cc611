#include <gtest/gtest.h>

#include "ari_social_sim/batch/progress_bar.hpp"

namespace ari_social_sim::batch {
namespace {

TEST(ProgressBar, BarCountRateAndTimeLeft) {
  // 50 of 100 in 48 s: 62.5 episodes per minute, 50 more take 48 s.
  EXPECT_EQ(progress_line(50, 100, 48.0),
            "[##########----------]  50/100 episodes  62.5 ep/min  ETA 0:48");
  EXPECT_EQ(progress_line(0, 100, 3.0), "[--------------------]   0/100 episodes");
  EXPECT_EQ(progress_line(7, 7, 14.0, 10), "[##########] 7/7 episodes  30.0 ep/min  ETA 0:00");
  // 1 of 1000 in 10 s: 999 more take 9990 s = 2:46:30.
  EXPECT_EQ(progress_line(1, 1000, 10.0, 4), "[----]    1/1000 episodes  6.0 ep/min  ETA 2:46:30");
}

TEST(ProgressBar, Durations) {
  EXPECT_EQ(format_duration(0.4), "0:00");
  EXPECT_EQ(format_duration(61.0), "1:01");
  EXPECT_EQ(format_duration(3599.6), "1:00:00");
  EXPECT_EQ(format_duration(-3.0), "0:00");
}

}  // namespace
}  // namespace ari_social_sim::batch
