#pragma once

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/physics/diff_drive_controller.hpp"

namespace ari_social_sim::physics {

/// Dead reckoning from the wheel joint angles, as diff_drive_controller's odometry: each tick's
/// wheel rotations give an arc, integrated with the second-order Runge-Kutta rule (heading at the
/// middle of the tick). The pose is base_footprint in the odom frame.
class WheelOdometry {
 public:
  WheelOdometry(const DriveGeometry& geometry, const core::Pose2& start)
      : geometry_(geometry), pose_(start) {}

  /// Wheel joint angles (rad, positive rolls forward) and their rates after a tick of `dt_s`.
  void update(double left_angle_rad, double right_angle_rad, double left_rate_rps,
              double right_rate_rps);

  const core::Pose2& pose() const { return pose_; }
  double linear_mps() const { return linear_mps_; }
  double angular_rps() const { return angular_rps_; }

 private:
  DriveGeometry geometry_;
  core::Pose2 pose_;
  bool has_angles_{false};
  double left_angle_rad_{0.0};
  double right_angle_rad_{0.0};
  double linear_mps_{0.0};
  double angular_rps_{0.0};
};

}  // namespace ari_social_sim::physics
