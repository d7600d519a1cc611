#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/gaze_generator.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

HumanSpec person(model::ObjectId id, double x, double y) {
  HumanSpec spec;
  spec.id = id;
  spec.pose.position = {x, y};
  return spec;
}

// D6.4 §3.3.2: over 10,000 s each target's share of time matches its probability and the mean
// dwell matches mean_duration. The share's standard deviation is sqrt(mean (2p - p^2) / T): with a
// 0.5 s mean it is at most 0.006, so the 0.02 band is over 3 sigma for every target; a 0.02 s step
// keeps the exponential's short dwells resolved.
TEST(GazeGenerator, SharesOfTimeAndMeanDwellMatchTheModel) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{0.02, 42, 0.05});
  simulation.add_human(person(11, 2.0, 2.0));
  simulation.add_human(person(12, 4.0, 2.0));
  simulation.add_human(person(13, 3.0, 4.0));
  HumanSpec watcher = person(10, 3.0, 3.0);
  GazeModel model;
  model.targets = {{11, 0.5}, {12, 0.3}, {13, 0.2}};
  model.mean_duration_s = 0.5;
  watcher.gaze = model;
  const Human& human = simulation.add_human(watcher);

  std::map<model::ObjectId, int> steps_on;
  int events = 0;
  double last_since = -1.0;
  const int steps = static_cast<int>(10000.0 / 0.02);
  for (int i = 0; i < steps; ++i) {
    simulation.step();
    ++steps_on[human.gaze()->target()];
    if (human.gaze()->since_s() != last_since) {
      ++events;
      last_since = human.gaze()->since_s();
    }
  }
  EXPECT_NEAR(steps_on[11] / double(steps), 0.5, 0.02);
  EXPECT_NEAR(steps_on[12] / double(steps), 0.3, 0.02);
  EXPECT_NEAR(steps_on[13] / double(steps), 0.2, 0.02);
  // Each event starts a dwell; 10,000 s / events is the mean dwell (about 20,000 events, standard
  // error 1 / sqrt(20000) = 0.7%).
  EXPECT_NEAR(10000.0 / events, 0.5, 0.05 * 0.5);
  std::printf(
      "shares of time 11/12/13: %.4f %.4f %.4f (model 0.5 0.3 0.2), mean dwell %.4f s "
      "(mean_duration 0.5 s) over %d dwells\n",
      steps_on[11] / double(steps), steps_on[12] / double(steps), steps_on[13] / double(steps),
      10000.0 / events, events);
}

TEST(GazeGenerator, DirectionFollowsTheTargetAndDistributionModeSamplesAroundTheHeading) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{0.05, 5, 0.05});
  simulation.add_human(person(11, 4.0, 4.0));
  HumanSpec watcher = person(10, 2.0, 2.0);
  watcher.gaze = GazeModel{{{11, 1.0}}, std::nullopt, 1.0};
  const Human& looking = simulation.add_human(watcher);

  HumanSpec wanderer = person(12, 2.0, 4.5);
  wanderer.pose.theta = 1.0;
  GazeModel directions;
  directions.directions = GazeDirections{GazeDirections::Distribution::kUniform, -0.5, 0.5};
  wanderer.gaze = directions;
  const Human& wandering = simulation.add_human(wanderer);

  double min_offset = 10, max_offset = -10;
  for (int i = 0; i < 4000; ++i) {
    simulation.step();
    // (2, 2) -> (4, 4): 45 degrees.
    ASSERT_NEAR(looking.gaze()->direction_rad(), M_PI / 4, 1e-6);
    const double offset = wandering.gaze()->direction_rad() - wandering.pose().theta;
    min_offset = std::min(min_offset, offset);
    max_offset = std::max(max_offset, offset);
    ASSERT_EQ(wandering.gaze()->target(), model::kNoObject);
  }
  // About 200 draws from U(-0.5, 0.5): the extremes come within 0.05 of the bounds.
  EXPECT_GE(min_offset, -0.5);
  EXPECT_LE(max_offset, 0.5);
  EXPECT_LT(min_offset, -0.45);
  EXPECT_GT(max_offset, 0.45);
}

TEST(GazeGenerator, ALostTargetIsReplacedAtOnce) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{0.05, 5, 0.05});
  simulation.add_human(person(11, 4.0, 4.0));
  simulation.add_human(person(12, 4.0, 2.0));
  HumanSpec watcher = person(10, 2.0, 2.0);
  watcher.gaze = GazeModel{{{11, 0.5}, {12, 0.5}}, std::nullopt, 100.0};
  const Human& human = simulation.add_human(watcher);
  simulation.step();
  const model::ObjectId first = human.gaze()->target();
  simulation.remove_human(first);
  simulation.step();
  EXPECT_EQ(human.gaze()->target(), first == 11 ? 12u : 11u);
}

TEST(GazeGenerator, InvalidModelsAreRejectedWithTheReason) {
  GazeModel sum_not_one{{{11, 0.5}, {12, 0.4}}, std::nullopt, 1.0};
  EXPECT_THROW(sum_not_one.validate(), core::RequestError);
  GazeModel no_mean{{{11, 1.0}}, std::nullopt, 0.0};
  EXPECT_THROW(no_mean.validate(), core::RequestError);
  GazeModel neither;
  EXPECT_THROW(neither.validate(), core::RequestError);
}

}  // namespace
}  // namespace ari_social_sim::world
