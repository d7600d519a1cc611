#include "ari_social_sim/world/differential_drive.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::world {
namespace {

double approach(double current, double target, double max_change) {
  return current + std::clamp(target - current, -max_change, max_change);
}

}  // namespace

bool DifferentialDrive::command(double linear_mps, double angular_rps, double now_s) {
  // std::clamp passes NaN through: requests are checked by Simulation::command_ari_twist.
  ARI_DCHECK(std::isfinite(linear_mps) && std::isfinite(angular_rps));
  commanded_linear_mps_ = std::clamp(linear_mps, limits_.min_linear_mps, limits_.max_linear_mps);
  commanded_angular_rps_ =
      std::clamp(angular_rps, -limits_.max_angular_rps, limits_.max_angular_rps);
  command_time_s_ = now_s;
  return commanded_linear_mps_ != linear_mps || commanded_angular_rps_ != angular_rps;
}

void DifferentialDrive::step(Object& owner, const StepContext& context) {
  const bool fresh = context.time_s - command_time_s_ <= limits_.cmd_vel_timeout_s;
  const double target_linear = fresh ? commanded_linear_mps_ : 0.0;
  const double target_angular = fresh ? commanded_angular_rps_ : 0.0;
  linear_mps_ = approach(linear_mps_, target_linear, limits_.max_linear_accel_mps2 * context.dt_s);
  angular_rps_ =
      approach(angular_rps_, target_angular, limits_.max_angular_accel_rps2 * context.dt_s);
  ARI_DCHECK(std::isfinite(linear_mps_) && std::isfinite(angular_rps_));
}

}  // namespace ari_social_sim::world
