#pragma once

#include <limits>

#include "ari_social_sim/core/config_fields.hpp"

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

  /// The limits' bounds (config_fields.hpp); the world checks them in AriSpec::validate.
  template <class V>
  void visit(V& v) {
    v.field("max_linear", max_linear_mps, "m/s, fastest forward speed", core::positive());
    v.field("min_linear", min_linear_mps, "m/s, fastest backward speed (<= 0)",
            {-std::numeric_limits<double>::infinity(), 0.0, false});
    v.field("max_linear_accel", max_linear_accel_mps2, "m/s^2", core::positive());
    v.field("max_angular", max_angular_rps, "rad/s", core::positive());
    v.field("max_angular_accel", max_angular_accel_rps2, "rad/s^2", core::positive());
    v.field("head_pan_limit", head_pan_limit_rad, "rad, head_1_joint's limit either way",
            core::positive());
    v.field("head_pan_max_speed", head_pan_max_speed_rps, "rad/s", core::positive());
    v.field("cmd_vel_timeout", cmd_vel_timeout_s, "s without commands before the base stops",
            core::positive());
  }
};

}  // namespace ari_social_sim::model
