#include "ari_social_sim/engine/in_process_navigation.hpp"

#include "ari_social_sim/engine/ari_observation.hpp"
#include "ari_social_sim/perception/tracked_persons.hpp"

namespace ari_social_sim::engine {

scenario::NavigationStatus as_seen_by_the_script(const navigation::GoalStatus& goal) {
  switch (goal.state) {
    case navigation::GoalState::kPending:
    case navigation::GoalState::kActive:
      return {scenario::NavigationState::kActive, ""};
    case navigation::GoalState::kSucceeded:
      return {scenario::NavigationState::kSucceeded, ""};
    case navigation::GoalState::kRejected:
    case navigation::GoalState::kAborted:
      return {scenario::NavigationState::kFailed, goal.reason};
    case navigation::GoalState::kCanceled:
      break;
  }
  return {};
}

InProcessNavigation::InProcessNavigation(const navigation::NavigationConfig& config,
                                         const model::OccupancyGrid& map,
                                         world::Simulation& simulation,
                                         std::shared_ptr<navigation::Policy> policy)
    : simulation_(simulation), session_(config, std::move(policy)) {
  session_.set_map(map);
  perceived_.locate_body = [](const std::string&) { return std::nullopt; };
}

void InProcessNavigation::perceive(const perception::PerceptionFrame& frame) {
  perceived_ = perception::tracked_persons_of(frame);
}

void InProcessNavigation::receive_groups(const std::vector<perception::PerceivedGroup>& groups,
                                         double time_s) {
  for (const perception::PerceivedGroup& group : groups) {
    session_.receive_group({group.group_id, time_s, group.members});
  }
}

void InProcessNavigation::start(const navigation::NavigationTarget& target) {
  const navigation::SessionOutput out = session_.request(target, inputs());
  goal_ = session_.newest_goal();
  apply(out);
}

void InProcessNavigation::cancel() {
  if (goal_ != 0) {
    apply(session_.cancel(goal_));
  }
  goal_ = 0;
  status_ = {};
}

void InProcessNavigation::fail(const std::string& reason) {
  cancel();
  status_ = {scenario::NavigationState::kFailed, reason};
}

void InProcessNavigation::control() {
  apply(session_.control(inputs()));
}

// As social_mpc_node sees the world: the sim time, ARI as its odometry, joint states and tf
// measure it (nothing without ARI: world_node publishes no base frame then), the latest persons.
navigation::SessionInputs InProcessNavigation::inputs() const {
  navigation::SessionInputs inputs;
  inputs.now_s = simulation_.time_s();
  if (simulation_.ari() != nullptr) {
    inputs.robot = observe_ari(*simulation_.ari());
  }
  inputs.perception = perceived_;
  return inputs;
}

void InProcessNavigation::apply(const navigation::SessionOutput& out) {
  for (const navigation::GoalChange& change : out.goals) {
    if (change.goal == goal_) {
      status_ = as_seen_by_the_script(change.status);
    }
  }
  // As world_node applies /mobile_base_controller/cmd_vel and /head_controller/command.
  for (const navigation::BaseCommand& command : out.commands) {
    if (simulation_.ari() != nullptr) {
      simulation_.command_ari_twist(command.linear_mps, command.angular_rps);
      if (command.pan_rad) {
        simulation_.command_ari_head_pan(*command.pan_rad);
      }
    }
    sent_.push_back(command);
  }
}

std::vector<navigation::BaseCommand> InProcessNavigation::take_commands() {
  std::vector<navigation::BaseCommand> taken = std::move(sent_);
  sent_.clear();
  return taken;
}

}  // namespace ari_social_sim::engine
