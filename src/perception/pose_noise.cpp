#include "ari_social_sim/perception/pose_noise.hpp"

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::perception {

core::Pose2 perturb_pose(const PoseNoise& noise, const core::Pose2& truth, double distance_m,
                         core::Rng& rng) {
  core::Pose2 pose = truth;
  const double position_stddev = noise.position_stddev_m(distance_m);
  if (position_stddev > 0.0) {
    pose.position.x() += rng.normal(0.0, position_stddev);
    pose.position.y() += rng.normal(0.0, position_stddev);
  }
  const double orientation_stddev = core::deg_to_rad(noise.orientation_stddev_deg(distance_m));
  if (orientation_stddev > 0.0) {
    pose.theta = core::wrap_angle(pose.theta + rng.normal(0.0, orientation_stddev));
  }
  return pose;
}

}  // namespace ari_social_sim::perception
