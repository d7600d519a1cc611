#pragma once

#include "ari_social_sim/model/ari_limits.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// ARI's base as PAL's diff_drive_controller drives it (D6.4 §3.5.5: linear velocity along the body
/// heading, angular velocity of the body): the commanded twist is clamped to the velocity limits,
/// reached within the acceleration limits, and dropped to zero after the command timeout.
class DifferentialDrive : public Component {
 public:
  explicit DifferentialDrive(const model::AriLimits& limits) : limits_(limits) {}

  ComponentPhase phase() const override { return ComponentPhase::kGenerator; }
  void step(Object& owner, const StepContext& context) override;

  /// A twist command received at sim time `now_s`. Returns true if it had to be clamped.
  bool command(double linear_mps, double angular_rps, double now_s);

  double linear_mps() const { return linear_mps_; }
  double angular_rps() const { return angular_rps_; }

 private:
  model::AriLimits limits_;
  double commanded_linear_mps_{0.0};
  double commanded_angular_rps_{0.0};
  double command_time_s_{-1e9};
  double linear_mps_{0.0};
  double angular_rps_{0.0};
};

}  // namespace ari_social_sim::world
