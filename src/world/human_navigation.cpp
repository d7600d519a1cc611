#include "ari_social_sim/world/human_navigation.hpp"

#include <cmath>

#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/social_forces.hpp"
#include "ari_social_sim/world/step_motion.hpp"

namespace ari_social_sim::world {

void HumanNavigation::step(Object& owner, const StepContext& context) {
  auto& human = static_cast<Human&>(owner);
  if (human.motion_mode() != MotionMode::kNavigation || !goal_) {
    return;
  }
  const HumanMotionParams& params = human.spec().motion;
  const Eigen::Vector2d p = human.pose().position;

  // Eq. 3.1: goal force plus repulsion from every agent inside the personal area.
  context.simulation.agent_centres_near(p, params.personal_distance_m, &human, neighbours_);
  const Eigen::Vector2d force =
      social_forces::goal_force(p, goal_->position, params.goal_distance_m) +
      social_forces::repulsion_force(p, neighbours_, params.personal_distance_m);

  // Eq. 3.3 and 3.2/3.4: step along the force, turn toward the movement, then the goal heading.
  const StepMotion motion = step_motion(force, params);
  const double theta = human.pose().theta;
  const double theta_move = motion.is_moving() ? motion.direction_rad() : theta;
  const double turn = social_forces::navigation_rotation(
      theta, theta_move, goal_->theta, (goal_->position - p).norm(), params.goal_distance_m);
  human.plan_motion(motion.velocity_mps, rotation_step(turn, params, context.dt_s));
}

}  // namespace ari_social_sim::world
