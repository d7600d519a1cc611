#pragma once

namespace ari_social_sim::model {

/// ARI's actuation limits (ari_robot's mobile_base_controller and head controller configuration,
/// see docs/references.md). Commands outside them are clamped, as ARI's controllers do.
struct AriLimits {
  double max_linear_mps{1.0};
  double min_linear_mps{-0.2};
  double max_linear_accel_mps2{1.0};
  double max_angular_rps{2.094};         // 120 deg/s
  double max_angular_accel_rps2{2.094};  // 120 deg/s^2
  double head_pan_limit_rad{1.309};      // head_1_joint +-75 deg
  double head_pan_max_speed_rps{3.0};
  double cmd_vel_timeout_s{0.25};  // base stops when commands stop for this long
};

}  // namespace ari_social_sim::model
