#pragma once

#include <actionlib/server/action_server.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <unordered_map>

#include "ari_social_sim/PointHeadAction.h"
#include "ari_social_sim/physics/ari_physics.hpp"
#include "ari_social_sim/physics/point_head.hpp"
#include "ari_social_sim/physics/point_head_goal.hpp"
#include "node_support/renewing_tf_buffer.hpp"
#include "sim_clock.hpp"

namespace ari_social_sim::nodes {

/// /head_controller/point_head_action as PAL's head_action serves it: solve pan and tilt for the
/// target, send them to head_controller, report the pointing error until it is below 0.01 rad.
/// A target in a tf frame (a person, perception's frames) is looked up without waiting, as this
/// runs in the thread that makes sim time: a goal whose frame tf does not know yet is accepted
/// and waits kTfWaitS of wall time for it; a frame that stops coming while the goal runs aborts
/// it. Either way the error names the frame.
class PointHeadInterface {
 public:
  using Server = actionlib::ActionServer<PointHeadAction>;

  PointHeadInterface(ros::NodeHandle& nh, physics::AriPhysics& physics, const SimClock& clock,
                     const RenewingTfBuffer& tf);

  /// Reports the active goal's outcome and feedback; aborts it when its tf frame never comes or
  /// stops coming.
  void update_goal();

 private:
  /// The head's trajectory for a goal, with what it aims at.
  struct HeadMove {
    physics::TrajectoryRequest trajectory;
    double duration_s{0.0};
    Eigen::Vector3d target_base{Eigen::Vector3d::Zero()};
  };

  static physics::PointHeadGoal goal_of(const PointHeadGoal& msg);

  static double wall_now_s() { return ros::WallTime::now().toSec(); }

  std::unordered_map<std::string, double> joint_positions() const;

  double error_now() const;

  double max_velocity_rps(const char* joint) const;

  // ARI's own frames, map and odom come from the physics; any other frame through tf.
  bool is_tf_frame(const std::string& frame) const;

  // The newest transform from `frame` to base_footprint, without waiting; nothing (and the
  // reason in `error`) when tf cannot give one.
  std::optional<geometry_msgs::TransformStamped> latest_tf(const std::string& frame,
                                                           std::string* error) const;

  // The target in base_footprint; nothing while tf does not know its frame.
  std::optional<Eigen::Vector3d> target_in_base(const physics::PointHeadGoal& goal) const;

  // Pan and tilt for the target, timed as PAL's head_action times them; throws core::RequestError
  // for a target out of reach or a move too slow.
  HeadMove plan_move(const physics::PointHeadGoal& goal, const Eigen::Vector3d& target_base) const;

  void start_move(const HeadMove& move);

  void abort(const std::string& message);

  // Watches the active goal's tf frame: starts the move once the frame is there, aborts the
  // goal when it never comes or stops coming. True while the goal goes on with its frame.
  bool target_still_in_tf();

  void on_goal(Server::GoalHandle goal);

  void on_cancel(const Server::GoalHandle& goal);

  physics::AriPhysics& physics_;
  const SimClock& clock_;
  const RenewingTfBuffer& tf_;
  physics::PointHeadSolver solver_;
  physics::TrajectoryController& head_;
  Server server_;
  std::optional<Server::GoalHandle> active_;
  physics::PointHeadGoal goal_;  // the active goal's, defaults filled in
  bool moving_{false};           // the head's trajectory for the active goal was sent
  physics::FrameWatch watch_;
  uint64_t head_goal_id_{0};
  double settle_deadline_s_{0.0};
  Eigen::Vector3d target_base_{Eigen::Vector3d::Zero()};
};

}  // namespace ari_social_sim::nodes
