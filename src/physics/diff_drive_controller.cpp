#include "ari_social_sim/physics/diff_drive_controller.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::physics {

bool DiffDriveController::command(double linear_mps, double angular_rps, double now_s) {
  // preserve_turning_radius: one factor for both components, the smallest any limit asks for.
  double scale = 1.0;
  if (linear_mps > limits_.max_linear_mps) {
    scale = std::min(scale, limits_.max_linear_mps / linear_mps);
  } else if (linear_mps < limits_.min_linear_mps) {
    scale = std::min(scale, limits_.min_linear_mps / linear_mps);
  }
  if (std::abs(angular_rps) > limits_.max_angular_rps) {
    scale = std::min(scale, limits_.max_angular_rps / std::abs(angular_rps));
  }
  commanded_linear_mps_ = linear_mps * scale;
  commanded_angular_rps_ = angular_rps * scale;
  command_time_s_ = now_s;
  return scale < 1.0;
}

void DiffDriveController::update(double now_s, double dt_s) {
  const bool fresh = now_s - command_time_s_ <= limits_.cmd_vel_timeout_s;
  const double target_linear = fresh ? commanded_linear_mps_ : 0.0;
  const double target_angular = fresh ? commanded_angular_rps_ : 0.0;
  const double max_dv = limits_.max_linear_accel_mps2 * dt_s;
  const double max_dw = limits_.max_angular_accel_rps2 * dt_s;
  linear_mps_ += std::clamp(target_linear - linear_mps_, -max_dv, max_dv);
  angular_rps_ += std::clamp(target_angular - angular_rps_, -max_dw, max_dw);
}

double DiffDriveController::left_wheel_rps() const {
  return (linear_mps_ - 0.5 * angular_rps_ * geometry_.wheel_separation_m) /
         geometry_.wheel_radius_m;
}

double DiffDriveController::right_wheel_rps() const {
  return (linear_mps_ + 0.5 * angular_rps_ * geometry_.wheel_separation_m) /
         geometry_.wheel_radius_m;
}

}  // namespace ari_social_sim::physics
