#include "odom_frame.hpp"

#include <cmath>

#include "node_support/frames.hpp"

namespace ari_social_sim::nodes {

Eigen::Isometry3d planar(const core::Pose2& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(pose.position.x(), pose.position.y(), 0.0);
  X.linear() = Eigen::AngleAxisd(pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

core::Pose2 odom_in_map(const physics::AriPhysics& physics) {
  const Eigen::Isometry3d X_map_base = physics.frame_pose(kBaseFrame);
  const core::Pose2& base_in_odom = physics.odometry().pose();
  core::Pose2 odom;
  odom.theta = core::wrap_angle(std::atan2(X_map_base.linear()(1, 0), X_map_base.linear()(0, 0)) -
                                base_in_odom.theta);
  odom.position =
      X_map_base.translation().head<2>() - Eigen::Rotation2Dd(odom.theta) * base_in_odom.position;
  return odom;
}

}  // namespace ari_social_sim::nodes
