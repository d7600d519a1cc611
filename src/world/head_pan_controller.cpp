#include "ari_social_sim/world/head_pan_controller.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::world {

bool HeadPanController::command_velocity(double pan_velocity_rps) {
  // std::clamp passes NaN through: requests are checked by the Simulation's head commands.
  ARI_DCHECK(std::isfinite(pan_velocity_rps));
  has_target_ = false;
  commanded_velocity_rps_ =
      std::clamp(pan_velocity_rps, -limits_.head_pan_max_speed_rps, limits_.head_pan_max_speed_rps);
  return commanded_velocity_rps_ != pan_velocity_rps;
}

bool HeadPanController::command_position(double pan_rad) {
  ARI_DCHECK(std::isfinite(pan_rad));
  has_target_ = true;
  target_rad_ = std::clamp(pan_rad, -limits_.head_pan_limit_rad, limits_.head_pan_limit_rad);
  return target_rad_ != pan_rad;
}

void HeadPanController::step(Object& owner, const StepContext& context) {
  const double max_move = limits_.head_pan_max_speed_rps * context.dt_s;
  const double move = has_target_ ? std::clamp(target_rad_ - pan_rad_, -max_move, max_move)
                                  : commanded_velocity_rps_ * context.dt_s;
  const double next =
      std::clamp(pan_rad_ + move, -limits_.head_pan_limit_rad, limits_.head_pan_limit_rad);
  velocity_rps_ = (next - pan_rad_) / context.dt_s;
  pan_rad_ = next;
  ARI_DCHECK(std::isfinite(pan_rad_));
}

}  // namespace ari_social_sim::world
