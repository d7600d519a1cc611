// The ~max_rate gate on sim times: which world states perception takes.

#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/perception/rate_gate.hpp"

namespace ari_social_sim::perception {
namespace {

// World states at the world's step times (Simulation::time_s: step count x step), for `seconds`.
int taken_of_steps(RateGate& gate, double step_s, int steps) {
  int taken = 0;
  for (int k = 0; k <= steps; ++k) {
    taken += gate.take(static_cast<double>(k) * step_s) ? 1 : 0;
  }
  return taken;
}

TEST(RateGateTest, TheFirstStateIsTakenAndOneTooSoonAfterItIsNot) {
  RateGate gate(10.0);  // a period of 0.1 s: states 0.0999 s apart or more are due
  EXPECT_TRUE(gate.take(3.0));
  EXPECT_FALSE(gate.take(3.0));  // the same stamp again
  EXPECT_FALSE(gate.take(3.05));
  EXPECT_FALSE(gate.take(3.0998));
  EXPECT_TRUE(gate.take(3.0999 + 1e-9));
  // Counted from the last state taken (3.0999), not from the last one offered.
  EXPECT_FALSE(gate.take(3.19));
  EXPECT_TRUE(gate.take(3.2));
}

TEST(RateGateTest, TheBoundaryIsExactly0999OfAPeriod) {
  const double boundary_s = 0.999 * (1.0 / 10.0);
  RateGate gate(10.0);
  EXPECT_TRUE(gate.take(0.0));
  EXPECT_FALSE(gate.take(std::nextafter(boundary_s, 0.0)));
  EXPECT_TRUE(gate.take(boundary_s));
}

TEST(RateGateTest, AWorldSteppingAtExactlyTheMaximumRateIsNotThinnedOut) {
  // 20 Hz steps of 0.05 s, whose differences round to a little under 0.05 now and then.
  RateGate at_step_rate(20.0);
  EXPECT_EQ(taken_of_steps(at_step_rate, 0.05, 1000), 1001);
  // A 30 Hz gate (the default) takes every 20 Hz step too.
  RateGate faster(30.0);
  EXPECT_EQ(taken_of_steps(faster, 0.05, 1000), 1001);
  // Steps of 1/30 s at 30 Hz: every one.
  RateGate at_thirty(30.0);
  EXPECT_EQ(taken_of_steps(at_thirty, 1.0 / 30.0, 900), 901);
}

TEST(RateGateTest, ASlowerGateTakesEveryNthStep) {
  // 10 Hz on 0.05 s steps: 0.0, 0.1, 0.2, ... (every other step).
  RateGate half(10.0);
  EXPECT_EQ(taken_of_steps(half, 0.05, 1000), 501);
  // 7 Hz on 0.05 s steps: a period of 0.142857 s, so each third step (0.15 s apart).
  RateGate seven(7.0);
  EXPECT_EQ(taken_of_steps(seven, 0.05, 999), 334);
}

TEST(RateGateTest, TimeGoingBackwardsIsTakenAndCountsFromThere) {
  RateGate gate(10.0);
  EXPECT_TRUE(gate.take(42.0));
  EXPECT_TRUE(gate.take(0.0));  // /sim/reset: the world starts again at 0
  EXPECT_FALSE(gate.take(0.05));
  EXPECT_TRUE(gate.take(0.1));
  // Back by less than a period is still back: taken.
  EXPECT_TRUE(gate.take(0.08));
  EXPECT_FALSE(gate.take(0.12));
  EXPECT_TRUE(gate.take(0.18));
}

}  // namespace
}  // namespace ari_social_sim::perception
