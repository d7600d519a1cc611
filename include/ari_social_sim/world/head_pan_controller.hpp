#pragma once

#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// ARI's head pan (head_1_joint): driven by a pan velocity (D6.4 §3.5.5) or toward a position
/// target (what /head_controller/command gives), within the joint and speed limits.
class HeadPanController : public Component {
 public:
  HeadPanController(const model::AriLimits& limits, double initial_pan_rad)
      : limits_(limits), pan_rad_(initial_pan_rad) {}

  ComponentPhase phase() const override { return ComponentPhase::kGenerator; }
  void step(Object& owner, const StepContext& context) override;

  /// Moves at this velocity until another command. Returns true if it had to be clamped.
  bool command_velocity(double pan_velocity_rps);
  /// Moves to this pan at full speed and stops there. Returns true if it had to be clamped.
  bool command_position(double pan_rad);

  double pan_rad() const { return pan_rad_; }
  double pan_velocity_rps() const { return velocity_rps_; }

 private:
  model::AriLimits limits_;
  double pan_rad_;
  double velocity_rps_{0.0};
  double commanded_velocity_rps_{0.0};
  bool has_target_{false};
  double target_rad_{0.0};
};

}  // namespace ari_social_sim::world
