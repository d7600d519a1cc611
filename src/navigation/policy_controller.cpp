#include "ari_social_sim/navigation/policy_controller.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/signed_distance_field.hpp"

namespace ari_social_sim::navigation {

PolicyController::PolicyController(const NavigationConfig& config, const model::OccupancyGrid& map,
                                   std::shared_ptr<Policy> policy)
    : config_(core::validated(config)),
      policy_(std::move(policy)),
      footprint_(FootprintModel::covering(model::AriFootprint{}, config.mpc.footprint_circles)),
      goal_finder_(config.goal_finder, footprint_, config.mpc.personal_space),
      sdf_(signed_distance_field(map)),
      map_(map),
      observation_(policy_->observation()),
      input_(observation_.size()) {}

void PolicyController::start(const NavigationTarget& target, const PerceivedScene& scene,
                             const RobotObservation& robot, double time_s) {
  check_target(target);
  GoalSearch search = goal_finder_.find(target, scene, sdf_, robot.pose);
  if (const auto* failure = std::get_if<GoalFailure>(&search)) {
    refuse_goal(*failure);
  }
  goal_ = std::move(std::get<Goal>(search));
  target_ = target;
  state_ = NavigationState::kActive;
  best_distance_m_ = (goal_->pose.position - robot.pose.position).norm();
  best_distance_time_s_ = time_s;
}

void PolicyController::cancel() {
  state_ = NavigationState::kIdle;
  target_.reset();
}

NavigatorStep PolicyController::finish(NavigationState state, const std::string& reason) {
  state_ = state;
  target_.reset();
  NavigatorStep step;
  step.state = state;
  step.phase = state == NavigationState::kSucceeded ? "arrived" : "aborted";
  step.reason = reason;
  return step;
}

NavigatorStep PolicyController::update(double time_s, const RobotObservation& robot,
                                       const PerceivedScene& scene) {
  if (state_ != NavigationState::kActive) {
    NavigatorStep idle;
    idle.state = state_;
    return idle;
  }
  // As in training (learning::NavEnv): while the target cannot be placed (hidden, out of view),
  // the last place stands.
  GoalSearch search = goal_finder_.find(*target_, scene, sdf_, robot.pose, goal_);
  if (auto* goal = std::get_if<Goal>(&search)) {
    goal_ = std::move(*goal);
  }

  const double distance = (goal_->pose.position - robot.pose.position).norm();
  const double heading_error =
      std::abs(core::angle_difference(goal_->pose.theta, robot.pose.theta));
  if (distance <= policy_->position_tolerance_m() &&
      heading_error <= policy_->heading_tolerance_rad()) {
    NavigatorStep done = finish(NavigationState::kSucceeded, "");
    done.command.pan_rad = robot.pan_rad;
    done.distance_to_goal_m = distance;
    return done;
  }
  if (distance < best_distance_m_ - config_.navigator.progress_distance_m) {
    best_distance_m_ = distance;
    best_distance_time_s_ = time_s;
  } else if (time_s - best_distance_time_s_ > config_.navigator.progress_timeout_s) {
    return finish(NavigationState::kAborted,
                  "no progress toward " + describe(*target_) + " for " +
                      std::to_string(config_.navigator.progress_timeout_s) + " s");
  }

  observation_.build(robot, scene, goal_, true, map_, input_.data());
  const std::array<double, Policy::kActions> action = policy_->act(input_.data());
  NavigatorStep step;
  step.state = NavigationState::kActive;
  step.phase = "policy";
  step.command = {action[0], action[1], action[2]};
  step.distance_to_goal_m = distance;
  return step;
}

}  // namespace ari_social_sim::navigation
