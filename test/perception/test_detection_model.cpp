#include <gtest/gtest.h>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/detection_model.hpp"

namespace ari_social_sim::perception {
namespace {

DetectionErrors only_base(double miss_rate) {
  return DetectionErrors{miss_rate, 0.0, 0.0, 10.0, 0.0, 0.0, 0.0, 0.0};
}

TEST(MissProbability, CombinesIndependentCauses) {
  const DetectionErrors errors{0.1, 0.2, 0.4, 10.0, 0.5, 0, 0, 0};
  // Close, centred, fully visible: the base rate.
  EXPECT_NEAR(miss_probability(errors, {0.0, 10.0, 1.0, 1.0, 0.2}), 0.1, 1e-12);
  // Half the range: distance term 0.2 * 0.5 = 0.1 -> 1 - 0.9 * 0.9 = 0.19.
  EXPECT_NEAR(miss_probability(errors, {5.0, 10.0, 1.0, 1.0, 0.2}), 0.19, 1e-12);
  // 5 deg inside the edge of a 10 deg band: border term 0.4 * 0.5 = 0.2 -> 1 - 0.9 * 0.8.
  EXPECT_NEAR(miss_probability(errors, {0.0, 10.0, core::deg_to_rad(5.0), 1.0, 0.2}), 0.28, 1e-12);
  // Visible 0.6 with a minimum of 0.2: occlusion term 0.5 * 0.4 / 0.8 = 0.25 -> 1 - 0.9 * 0.75.
  EXPECT_NEAR(miss_probability(errors, {0.0, 10.0, 1.0, 0.6, 0.2}), 0.325, 1e-12);
  // All at once, at the range, on the edge, at the minimum: 1 - 0.9 * 0.8 * 0.6 * 0.5.
  EXPECT_NEAR(miss_probability(errors, {10.0, 10.0, 0.0, 0.2, 0.2}), 0.784, 1e-12);
}

TEST(MissProbability, ZeroWithoutErrors) {
  EXPECT_EQ(miss_probability(only_base(0.0), {9.9, 10.0, 0.0, 0.25, 0.2}), 0.0);
}

TEST(DecideSighting, OutOfViewThenOccludedThenDetected) {
  const FieldOfView fov{{{0.0, 0.0}, 0.0}, core::kPi / 2, 10.0};
  core::Rng rng(1);
  const DetectionErrors none = only_base(0.0);
  EXPECT_EQ(decide_sighting(none, fov, {11.0, 0.0}, 1.0, 0.2, rng), Sighting::kOutOfView);
  EXPECT_EQ(decide_sighting(none, fov, {-1.0, 0.0}, 1.0, 0.2, rng), Sighting::kOutOfView);
  EXPECT_EQ(decide_sighting(none, fov, {3.0, 0.0}, 0.1, 0.2, rng), Sighting::kOccluded);
  EXPECT_EQ(decide_sighting(none, fov, {3.0, 0.0}, 0.0, 0.0, rng), Sighting::kOccluded);
  EXPECT_EQ(decide_sighting(none, fov, {3.0, 0.0}, 0.2, 0.2, rng), Sighting::kDetected);
  EXPECT_EQ(decide_sighting(only_base(1.0), fov, {3.0, 0.0}, 1.0, 0.2, rng), Sighting::kMissed);
}

// Must-show 3: over many seeded frames the measured miss rate is within 10 % (relative) of the
// configured one, for the base rate and for the distance-dependent one.
TEST(DecideSighting, MeasuredMissRatesMatchTheConfiguredOnes) {
  const FieldOfView fov{{{0.0, 0.0}, 0.0}, core::kPi / 2, 10.0};
  const DetectionErrors errors{0.05, 0.2, 0.0, 10.0, 0.0, 0, 0, 0};
  core::Rng rng(2024);
  const int frames = 40000;
  // At 1 m: 1 - 0.95 * (1 - 0.02) = 0.069; at 8 m: 1 - 0.95 * (1 - 0.16) = 0.202.
  for (const auto& [x, expected] : {std::pair{1.0, 0.069}, std::pair{8.0, 0.202}}) {
    int missed = 0;
    for (int i = 0; i < frames; ++i) {
      missed += decide_sighting(errors, fov, {x, 0.0}, 1.0, 0.2, rng) == Sighting::kMissed;
    }
    const double rate = static_cast<double>(missed) / frames;
    EXPECT_NEAR(rate, expected, 0.1 * expected) << "at " << x << " m";
    std::printf("[ measured ] miss rate at %.0f m: %.4f (configured %.4f)\n", x, rate, expected);
  }
}

}  // namespace
}  // namespace ari_social_sim::perception
