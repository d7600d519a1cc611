#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "ari_social_sim/rendering/weight_shifts.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kStepS = 0.1;

// One person's load_side every kStepS for an hour.
std::vector<double> an_hour_of(uint64_t seed, uint32_t id) {
  WeightShifts shifts(seed, id);
  std::vector<double> loads;
  for (int step = 0; step <= 36000; ++step) {
    loads.push_back(shifts.load_side(step * kStepS));
  }
  return loads;
}

TEST(WeightShifts, PeopleShiftAndFidgetAsOftenAsDuarteAndZatsiorskyMeasured) {
  // A fidget goes over to the other leg and comes back within 4 s; a shift stays there.
  constexpr double kFidgetAtMostS = 4.0;
  int people = 0, shifts = 0, fidgets = 0, samples = 0, on_one_leg = 0, on_left = 0;
  std::vector<double> fidget_gaps;
  for (uint32_t id = 1; id <= 200; ++id) {
    const std::vector<double> loads = an_hour_of(7, id);
    ++people;
    std::vector<double> crossings;
    for (size_t step = 1; step < loads.size(); ++step) {
      if ((loads[step] > 0.0) != (loads[step - 1] > 0.0)) {
        crossings.push_back(step * kStepS);
      }
    }
    double last_fidget_s = -1.0;
    for (size_t k = 0; k < crossings.size(); ++k) {
      if (k + 1 < crossings.size() && crossings[k + 1] - crossings[k] < kFidgetAtMostS) {
        ++fidgets;
        if (last_fidget_s >= 0.0) {
          fidget_gaps.push_back(crossings[k] - last_fidget_s);
        }
        last_fidget_s = crossings[k];
        ++k;
      } else {
        ++shifts;
      }
    }
    for (const double load : loads) {
      ++samples;
      on_one_leg += std::abs(load) == 1.0 ? 1 : 0;
      on_left += load > 0.0 ? 1 : 0;
    }
  }
  double mean_gap = 0.0, gap_variance = 0.0;
  for (const double gap : fidget_gaps) {
    mean_gap += gap / fidget_gaps.size();
  }
  for (const double gap : fidget_gaps) {
    gap_variance += (gap - mean_gap) * (gap - mean_gap) / fidget_gaps.size();
  }
  const double shift_every_s = 3600.0 * people / shifts;
  std::printf(
      "[ measured ] %d people for an hour: a shift every %.1f s, a fidget every %.1f s "
      "(sd %.1f s); on one leg %.1f %% of the time, on the left %.1f %%\n",
      people, shift_every_s, mean_gap, std::sqrt(gap_variance), 100.0 * on_one_leg / samples,
      100.0 * on_left / samples);
  // 199 s and 49 +- 16 s (1999); about 3,600 shifts and 14,000 fidgets in all.
  EXPECT_NEAR(shift_every_s, 199.0, 0.08 * 199.0);
  EXPECT_NEAR(mean_gap, 49.0, 0.04 * 49.0);
  EXPECT_NEAR(std::sqrt(gap_variance), 16.0, 0.15 * 16.0);
  // Moving over takes 0.8 s, 3600 / 199 + 2 x 3600 / 49 = 165 moves an hour: the rest of the
  // time on one leg.
  EXPECT_NEAR(100.0 * on_one_leg / samples, 100.0 * (1.0 - 165 * 0.8 / 3600.0), 0.5);
  EXPECT_NEAR(100.0 * on_left / samples, 50.0, 5.0);
}

TEST(WeightShifts, TheSameSeedAndPersonGiveTheSameMovesWhateverTheFramesAsked) {
  const std::vector<double> every_tenth = an_hour_of(3, 12);
  // Frames a minute apart, then going back in time, as a reader seeking through a run would.
  WeightShifts sparse(3, 12);
  for (const int step : {6000, 12000, 30000, 600, 36000, 0, 17777}) {
    EXPECT_EQ(sparse.load_side(step * kStepS), every_tenth[step]) << "at step " << step;
  }
  // Another person stands differently.
  const std::vector<double> other = an_hour_of(3, 13);
  int differ = 0;
  for (size_t step = 0; step < other.size(); ++step) {
    differ += other[step] != every_tenth[step] ? 1 : 0;
  }
  EXPECT_GT(differ, 10000);
}

TEST(WeightShifts, TheWeightMovesOverSmoothly) {
  const std::vector<double> loads = an_hour_of(5, 2);
  double largest_step = 0.0;
  for (size_t step = 1; step < loads.size(); ++step) {
    EXPECT_LE(std::abs(loads[step]), 1.0);
    largest_step = std::max(largest_step, std::abs(loads[step] - loads[step - 1]));
  }
  // A smoothstep over 0.8 s from -1 to +1 moves at most 2 x 1.5 / 0.8 per second.
  EXPECT_LE(largest_step, 2.0 * 1.5 / 0.8 * kStepS + 1e-9);
  EXPECT_GT(largest_step, 0.2);
}

}  // namespace
}  // namespace ari_social_sim::rendering
