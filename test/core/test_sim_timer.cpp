#include <gtest/gtest.h>

#include <vector>

#include "ari_social_sim/core/clock_time.hpp"
#include "ari_social_sim/core/sim_timer.hpp"

namespace ari_social_sim::core {
namespace {

// The steps (1-based) at which a timer of `rate_hz` runs over `steps` steps of `step_s`.
std::vector<uint64_t> runs(double rate_hz, double step_s, uint64_t steps) {
  SimTimer timer(rate_hz);
  std::vector<uint64_t> due;
  for (uint64_t k = 1; k <= steps; ++k) {
    if (timer.due(clock_time_s(k, step_s))) {
      due.push_back(k);
    }
  }
  return due;
}

TEST(SimTimer, TwentyHertzRunsAtEveryDefaultStep) {
  EXPECT_EQ(runs(20.0, 0.05, 400).size(), 400u);
}

TEST(SimTimer, RunsAtTheFirstStepThatReachesEachPeriod) {
  // 20 Hz on 0.02 s steps: the periods end at 0.05, 0.10, 0.15, ...; the clock reaches them at
  // 0.06, 0.10, 0.16, 0.20 s (steps 3, 5, 8, 10), as a roscpp timer on /clock fires.
  EXPECT_EQ(runs(20.0, 0.02, 10), (std::vector<uint64_t>{3, 5, 8, 10}));
  // 10 Hz on 0.05 s steps: every other step.
  EXPECT_EQ(runs(10.0, 0.05, 6), (std::vector<uint64_t>{2, 4, 6}));
}

TEST(SimTimer, AJumpPastSeveralPeriodsRunsOnceAndTimeGoingBackRestarts) {
  SimTimer timer(20.0);
  EXPECT_FALSE(timer.due(0.02));
  EXPECT_TRUE(timer.due(1.0));  // 20 periods passed at once
  EXPECT_FALSE(timer.due(1.04));
  EXPECT_TRUE(timer.due(1.05));
  // A reset to 0: the next run is one period later, not at 1.1 s.
  EXPECT_FALSE(timer.due(0.0));
  EXPECT_FALSE(timer.due(0.03));
  EXPECT_TRUE(timer.due(0.05));
}

}  // namespace
}  // namespace ari_social_sim::core
