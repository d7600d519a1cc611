#include "controller_interface.hpp"

#include <algorithm>

#include "ari_social_sim/core/error.hpp"
#include "joint_trajectory.hpp"

namespace ari_social_sim::nodes {
namespace {

// JointTrajectoryController's action_monitor_rate (ari_robot's controller configuration).
constexpr double kActionMonitorRateHz = 20.0;

}  // namespace

ControllerInterface::ControllerInterface(ros::NodeHandle& nh,
                                         physics::TrajectoryController& controller,
                                         physics::AriPhysics& physics, const SimClock& clock)
    : controller_(controller),
      physics_(physics),
      clock_(clock),
      server_(nh, "/" + controller.spec().name + "/follow_joint_trajectory", false) {
  const std::string ns = "/" + controller.spec().name;
  command_sub_ = nh.subscribe(ns + "/command", 1, &ControllerInterface::on_command, this);
  state_pub_ = nh.advertise<JointTrajectoryControllerState>(ns + "/state", 10);
  query_ = nh.advertiseService(ns + "/query_state", &ControllerInterface::on_query, this);
  server_.registerGoalCallback([this](const Server::GoalHandle& goal) { on_goal(goal); });
  server_.registerCancelCallback([this](const Server::GoalHandle& goal) { on_cancel(goal); });
  server_.start();
}

void ControllerInterface::publish_state() {
  JointTrajectoryControllerState state = make_state();
  state_pub_.publish(state);
}

void ControllerInterface::update_goal() {
  if (!active_) {
    return;
  }
  const physics::GoalOutcome& outcome = controller_.goal();
  if (outcome.goal_id != active_id_ || outcome.state == physics::GoalState::kPreempted) {
    active_->setCanceled(FollowJointTrajectoryResult(), "preempted by a newer trajectory");
    active_.reset();
    return;
  }
  FollowJointTrajectoryResult result;
  result.error_code = static_cast<int32_t>(outcome.code);
  result.error_string = outcome.message;
  if (outcome.state == physics::GoalState::kSucceeded) {
    active_->setSucceeded(result);
    active_.reset();
  } else if (outcome.state == physics::GoalState::kAborted) {
    ROS_WARN("%s", outcome.message.c_str());
    active_->setAborted(result, outcome.message);
    active_.reset();
  } else if (clock_.now_s() >= next_feedback_s_) {
    next_feedback_s_ = clock_.now_s() + 1.0 / kActionMonitorRateHz;
    FollowJointTrajectoryFeedback feedback;
    const JointTrajectoryControllerState state = make_state();
    feedback.header = state.header;
    feedback.joint_names = state.joint_names;
    feedback.desired = state.desired;
    feedback.actual = state.actual;
    feedback.error = state.error;
    active_->publishFeedback(feedback);
  }
}

JointTrajectoryControllerState ControllerInterface::make_state() const {
  JointTrajectoryControllerState state;
  state.header.stamp = clock_.now();
  state.joint_names = controller_.spec().joints;
  state.desired = to_msg(controller_.desired());
  for (const std::string& joint : state.joint_names) {
    state.actual.positions.push_back(physics_.joint_position(joint));
  }
  state.actual.velocities.assign(state.joint_names.size(), 0.0);
  const std::vector<std::string>& names = physics_.joint_names();
  const std::vector<double> velocities = physics_.joint_velocities();
  for (size_t j = 0; j < state.joint_names.size(); ++j) {
    const auto it = std::find(names.begin(), names.end(), state.joint_names[j]);
    state.actual.velocities[j] = velocities[static_cast<size_t>(it - names.begin())];
    state.error.positions.push_back(state.desired.positions[j] - state.actual.positions[j]);
    state.error.velocities.push_back(state.desired.velocities[j] - state.actual.velocities[j]);
  }
  return state;
}

physics::TrajectoryRequest ControllerInterface::timed(physics::TrajectoryRequest request) const {
  request.start_time_s =
      request.start_time_s > 0.0 ? clock_.to_physics(ros::Time(request.start_time_s)) : 0.0;
  return request;
}

void ControllerInterface::on_command(const trajectory_msgs::JointTrajectory& trajectory) {
  try {
    controller_.follow(timed(from_msg(trajectory)), physics_.time_s(), false);
  } catch (const core::Error& e) {
    ROS_WARN("%s/command ignored: %s", controller_.spec().name.c_str(), e.what());
  }
}

void ControllerInterface::on_goal(Server::GoalHandle goal) {
  try {
    const uint64_t id =
        controller_.follow(timed(from_msg(*goal.getGoal())), physics_.time_s(), true);
    if (active_) {
      active_->setCanceled(FollowJointTrajectoryResult(), "preempted by a newer goal");
    }
    goal.setAccepted();
    active_ = goal;
    active_id_ = id;
    next_feedback_s_ = clock_.now_s();
  } catch (const physics::TrajectoryRejected& e) {
    FollowJointTrajectoryResult result;
    result.error_code = static_cast<int32_t>(e.code());
    result.error_string = e.what();
    ROS_WARN("%s", e.what());
    goal.setRejected(result, e.what());
  }
}

void ControllerInterface::on_cancel(const Server::GoalHandle& goal) {
  if (active_ && *active_ == goal) {
    controller_.cancel(active_id_, physics_.time_s());
    active_->setCanceled(FollowJointTrajectoryResult(), "canceled");
    active_.reset();
  }
}

bool ControllerInterface::on_query(QueryTrajectoryState::Request& request,
                                   QueryTrajectoryState::Response& response) {
  const physics::JointSetpoint state =
      controller_.sample(std::max(0.0, request.time.toSec() - clock_.origin_s));
  response.name = controller_.spec().joints;
  response.position = state.positions;
  response.velocity = state.velocities;
  response.acceleration = state.accelerations;
  return true;
}

}  // namespace ari_social_sim::nodes
