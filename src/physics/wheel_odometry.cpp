#include "ari_social_sim/physics/wheel_odometry.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::physics {

void WheelOdometry::update(double left_angle_rad, double right_angle_rad, double left_rate_rps,
                           double right_rate_rps) {
  const double r = geometry_.wheel_radius_m;
  const double b = geometry_.wheel_separation_m;
  linear_mps_ = 0.5 * r * (left_rate_rps + right_rate_rps);
  angular_rps_ = r * (right_rate_rps - left_rate_rps) / b;
  if (!has_angles_) {
    has_angles_ = true;
    left_angle_rad_ = left_angle_rad;
    right_angle_rad_ = right_angle_rad;
    return;
  }
  const double left_m = r * (left_angle_rad - left_angle_rad_);
  const double right_m = r * (right_angle_rad - right_angle_rad_);
  left_angle_rad_ = left_angle_rad;
  right_angle_rad_ = right_angle_rad;
  const double distance = 0.5 * (left_m + right_m);
  const double turn = (right_m - left_m) / b;
  const double mid_heading = pose_.theta + 0.5 * turn;
  pose_.position.x() += distance * std::cos(mid_heading);
  pose_.position.y() += distance * std::sin(mid_heading);
  pose_.theta = core::wrap_angle(pose_.theta + turn);
}

}  // namespace ari_social_sim::physics
