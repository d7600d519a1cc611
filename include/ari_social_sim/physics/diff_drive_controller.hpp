#pragma once

#include "ari_social_sim/model/ari_limits.hpp"

namespace ari_social_sim::physics {

/// Wheel radius and separation of a differential drive (m), read from the URDF as PAL's
/// diff_drive_controller does.
struct DriveGeometry {
  double wheel_radius_m{0.125};
  double wheel_separation_m{0.44};
};

/// ARI's mobile_base_controller (diff_drive_controller, ari_robot) turning a twist command
/// into wheel velocities: velocity limits with preserve_turning_radius (both components scaled by
/// the same factor so the path's curvature is kept), then acceleration limits per component, and
/// a stop (within the acceleration limits) when no command arrived for cmd_vel_timeout.
class DiffDriveController {
 public:
  DiffDriveController(const model::AriLimits& limits, const DriveGeometry& geometry)
      : limits_(limits), geometry_(geometry) {}

  /// A cmd_vel received at sim time `now_s`. Returns true if it had to be scaled to the limits.
  bool command(double linear_mps, double angular_rps, double now_s);
  /// Advances the limited twist by one tick of `dt_s` ending at `now_s`.
  void update(double now_s, double dt_s);

  /// The twist after limits (base_footprint: x forward, yaw rate).
  double linear_mps() const { return linear_mps_; }
  double angular_rps() const { return angular_rps_; }
  /// Wheel joint velocities (rad/s, positive rolls forward) realising that twist.
  double left_wheel_rps() const;
  double right_wheel_rps() const;

 private:
  model::AriLimits limits_;
  DriveGeometry geometry_;
  double commanded_linear_mps_{0.0};
  double commanded_angular_rps_{0.0};
  double command_time_s_{-1e9};
  double linear_mps_{0.0};
  double angular_rps_{0.0};
};

}  // namespace ari_social_sim::physics
