#pragma once

#include <actionlib/server/action_server.h>
#include <ros/ros.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cstdint>
#include <optional>

#include "ari_social_sim/FollowJointTrajectoryAction.h"
#include "ari_social_sim/JointTrajectoryControllerState.h"
#include "ari_social_sim/QueryTrajectoryState.h"
#include "ari_social_sim/physics/ari_physics.hpp"
#include "ari_social_sim/physics/trajectory_controller.hpp"
#include "sim_clock.hpp"

namespace ari_social_sim::nodes {

/// One joint trajectory controller's ROS face: /command, follow_joint_trajectory, /state,
/// query_state, with the names and semantics of ros_controllers.
class ControllerInterface {
 public:
  using Server = actionlib::ActionServer<FollowJointTrajectoryAction>;

  ControllerInterface(ros::NodeHandle& nh, physics::TrajectoryController& controller,
                      physics::AriPhysics& physics, const SimClock& clock);

  /// Publishes /state: desired, actual and error of the controller's joints now.
  void publish_state();

  /// Reports the active goal's outcome once the core has judged it; feedback at the action
  /// monitor rate.
  void update_goal();

 private:
  JointTrajectoryControllerState make_state() const;

  physics::TrajectoryRequest timed(physics::TrajectoryRequest request) const;

  void on_command(const trajectory_msgs::JointTrajectory& trajectory);

  void on_goal(Server::GoalHandle goal);

  void on_cancel(const Server::GoalHandle& goal);

  bool on_query(QueryTrajectoryState::Request& request, QueryTrajectoryState::Response& response);

  physics::TrajectoryController& controller_;
  physics::AriPhysics& physics_;
  const SimClock& clock_;
  Server server_;
  std::optional<Server::GoalHandle> active_;
  uint64_t active_id_{0};
  double next_feedback_s_{0.0};
  ros::Subscriber command_sub_;
  ros::Publisher state_pub_;
  ros::ServiceServer query_;
};

}  // namespace ari_social_sim::nodes
