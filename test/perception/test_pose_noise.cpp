#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/pose_noise.hpp"

namespace ari_social_sim::perception {
namespace {

struct Spread {
  double x_stddev{0.0};
  double y_stddev{0.0};
  double theta_stddev_deg{0.0};
};

Spread measure(const PoseNoise& noise, double distance_m, int samples, uint64_t seed) {
  core::Rng rng(seed);
  const core::Pose2 truth{{1.0, 2.0}, 0.5};
  double sx = 0, sy = 0, st = 0;
  for (int i = 0; i < samples; ++i) {
    const core::Pose2 pose = perturb_pose(noise, truth, distance_m, rng);
    sx += std::pow(pose.position.x() - truth.position.x(), 2);
    sy += std::pow(pose.position.y() - truth.position.y(), 2);
    st += std::pow(core::rad_to_deg(core::angle_difference(pose.theta, truth.theta)), 2);
  }
  return {std::sqrt(sx / samples), std::sqrt(sy / samples), std::sqrt(st / samples)};
}

TEST(PoseNoise, ZeroNoiseIsTheTruth) {
  core::Rng rng(1);
  const core::Pose2 truth{{1.0, 2.0}, 0.5};
  const core::Pose2 pose = perturb_pose(PoseNoise{0, 0, 0, 0}, truth, 7.0, rng);
  EXPECT_EQ(pose.position, truth.position);
  EXPECT_EQ(pose.theta, truth.theta);
}

// Must-show 3: the measured position and orientation standard deviations are within 10 % of the
// configured ones, and they grow with distance as configured.
TEST(PoseNoise, MeasuredStandardDeviationsMatchTheConfiguredOnes) {
  const PoseNoise noise{0.05, 0.02, 3.0, 2.0};
  for (double distance : {1.0, 6.0}) {
    // At 1 m: 0.07 m and 5 deg; at 6 m: 0.17 m and 15 deg.
    const double position = 0.05 + 0.02 * distance;
    const double orientation = 3.0 + 2.0 * distance;
    const Spread spread = measure(noise, distance, 20000, 99);
    EXPECT_NEAR(spread.x_stddev, position, 0.1 * position);
    EXPECT_NEAR(spread.y_stddev, position, 0.1 * position);
    EXPECT_NEAR(spread.theta_stddev_deg, orientation, 0.1 * orientation);
    std::printf(
        "[ measured ] at %.0f m: position sd %.4f/%.4f m (configured %.3f), orientation sd "
        "%.2f deg (configured %.1f)\n",
        distance, spread.x_stddev, spread.y_stddev, position, spread.theta_stddev_deg, orientation);
  }
}

}  // namespace
}  // namespace ari_social_sim::perception
