#pragma once

#include <optional>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// D6.4 §3.3.1 HumanNavigation: walks the owner toward a goal pose with a goal force (eq. 3.5) plus
/// repulsion from agents in its personal area (eq. 3.6-3.7), p += eta f (eq. 3.3), turning toward
/// the movement direction, then to the goal orientation within Delta_G (eq. 3.2, 3.4).
class HumanNavigation : public Component {
 public:
  ComponentPhase phase() const override { return ComponentPhase::kGenerator; }
  void step(Object& owner, const StepContext& context) override;

  void set_goal(const core::Pose2& goal) { goal_ = goal; }
  void clear_goal() { goal_.reset(); }
  const std::optional<core::Pose2>& goal() const { return goal_; }

 private:
  std::optional<core::Pose2> goal_;
  std::vector<Eigen::Vector2d> neighbours_;  // scratch, reused every step
};

}  // namespace ari_social_sim::world
