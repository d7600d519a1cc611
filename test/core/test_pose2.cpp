#include <gtest/gtest.h>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/pose2.hpp"

namespace ari_social_sim::core {
namespace {

TEST(Pose2, RelativeToIsTheInverseOfTransform) {
  const Pose2 frame{{2.0, 1.0}, kPi / 2};  // at (2, 1), facing +y
  const Pose2 pose{{2.0, 3.0}, kPi};       // 2 m ahead of it, facing -x (its left)
  const Pose2 local = pose.relative_to(frame);
  EXPECT_NEAR(local.position.x(), 2.0, 1e-12);
  EXPECT_NEAR(local.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(local.theta, kPi / 2, 1e-12);
  const Eigen::Vector2d back = frame.transform(local.position);
  EXPECT_NEAR(back.x(), pose.position.x(), 1e-12);
  EXPECT_NEAR(back.y(), pose.position.y(), 1e-12);
  // Headings are wrapped into [-pi, pi).
  EXPECT_NEAR((Pose2{{0, 0}, 3.0}.relative_to(Pose2{{0, 0}, -3.0})).theta, 6.0 - 2 * kPi, 1e-12);
}

}  // namespace
}  // namespace ari_social_sim::core
