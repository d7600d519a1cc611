#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/physics/joint_trajectory.hpp"

namespace ari_social_sim::physics {

/// Result codes of control_msgs/FollowJointTrajectoryResult (same values on the wire).
enum class TrajectoryErrorCode : int32_t {
  kSuccessful = 0,
  kInvalidGoal = -1,
  kInvalidJoints = -2,
  kOldHeaderTimestamp = -3,
  kPathToleranceViolated = -4,
  kGoalToleranceViolated = -5,
};

/// A trajectory the controller refuses, with the code a FollowJointTrajectory server returns.
class TrajectoryRejected : public core::RequestError {
 public:
  TrajectoryRejected(TrajectoryErrorCode code, const std::string& message)
      : core::RequestError(message), code_(code) {}
  TrajectoryErrorCode code() const { return code_; }

 private:
  TrajectoryErrorCode code_;
};

/// Position limits and top speed of one controlled joint (from the URDF).
struct JointBounds {
  double lower_rad{0.0};
  double upper_rad{0.0};
  double max_velocity_rps{0.0};
};

/// One joint trajectory controller as PAL configures it (ari_robot): the joints it owns and
/// the default constraints of position_controllers/JointTrajectoryController.
struct ControllerSpec {
  std::string name;                 // e.g. "head_controller"
  std::vector<std::string> joints;  // in the order of the controller's state messages
  double goal_tolerance_rad{0.02};  // per joint, at the end of the trajectory
  double goal_time_s{0.6};          // how long after the end the goal may take to be reached
  double stopped_velocity_tolerance_rps{5.0};
};

/// control_msgs/JointTolerance without ROS: 0 keeps the default, -1 removes the tolerance.
struct JointTolerance {
  std::string joint;
  double position{0.0};
  double velocity{0.0};
  double acceleration{0.0};
};

/// A trajectory request: what FollowJointTrajectory goals and /command messages carry.
struct TrajectoryRequest {
  std::vector<std::string> joint_names;
  std::vector<TrajectoryPoint> points;
  double start_time_s{0.0};  // sim time the points are timed from; 0 = when received
  std::vector<JointTolerance> path_tolerance;
  std::vector<JointTolerance> goal_tolerance;
  double goal_time_tolerance_s{0.0};  // 0 = the controller's goal_time
};

/// Where a monitored goal stands.
enum class GoalState { kNone, kActive, kSucceeded, kAborted, kPreempted };

struct GoalOutcome {
  uint64_t goal_id{0};
  GoalState state{GoalState::kNone};
  TrajectoryErrorCode code{TrajectoryErrorCode::kSuccessful};
  std::string message;
};

/// ros_controllers' JointTrajectoryController semantics on a set of position-controlled joints:
/// validates a request (joint names, sizes, timing, ARI's joint limits), splices it onto the
/// current setpoint, samples the desired state every tick, saturates the position command at the
/// joints' velocity and position limits (as ros_control's joint_limits_interface does), and judges
/// a monitored goal against its tolerances.
class TrajectoryController {
 public:
  /// `bounds` is indexed like spec.joints; `initial_positions` too.
  TrajectoryController(ControllerSpec spec, std::vector<JointBounds> bounds,
                       const std::vector<double>& initial_positions);

  const ControllerSpec& spec() const { return spec_; }

  /// Replaces the current trajectory at sim time `now_s`. A monitored request (an action goal)
  /// gets a goal id whose outcome goal() reports; an earlier monitored goal is preempted.
  /// Throws TrajectoryRejected (INVALID_JOINTS, INVALID_GOAL: check_trajectory_request, or
  /// OLD_HEADER_TIMESTAMP) and then leaves the current trajectory running.
  uint64_t follow(const TrajectoryRequest& request, double now_s, bool monitored);
  /// Cancels the monitored goal `goal_id` (if it is the active one) and holds position.
  void cancel(uint64_t goal_id, double now_s);

  /// One control tick: samples the desired state at `now_s`, saturates the command, judges the
  /// monitored goal against `actual` (positions and velocities of spec.joints). Never throws.
  void update(double now_s, double dt_s, const std::vector<double>& actual_positions,
              const std::vector<double>& actual_velocities);

  /// Position command for each joint after saturation (what the joint servos track).
  const std::vector<double>& command() const { return command_; }
  /// The trajectory's desired state at the last update.
  const JointSetpoint& desired() const { return desired_; }
  /// The active trajectory sampled at any time (the query_state service).
  JointSetpoint sample(double time_s) const { return trajectory_.sample(time_s); }
  const GoalOutcome& goal() const { return goal_; }

 private:
  std::vector<int> joint_permutation(const std::vector<std::string>& names) const;
  /// The limits of each column of a request whose joints are permuted by `permutation`.
  std::vector<JointBounds> bounds_by_column(const std::vector<int>& permutation) const;
  /// Throws INVALID_GOAL for a start more than kMaxTrajectoryTimeS ahead of `now_s`, and
  /// OLD_HEADER_TIMESTAMP for a stamped request whose last point is before `now_s`.
  void check_timing(const TrajectoryRequest& request, double start_s, double now_s,
                    const std::string& trajectory_field) const;
  double tolerance_for(const std::vector<JointTolerance>& tolerances, size_t joint,
                       double fallback) const;

  ControllerSpec spec_;
  std::vector<JointBounds> bounds_;
  JointTrajectory trajectory_;
  JointSetpoint desired_;
  std::vector<double> command_;

  GoalOutcome goal_;
  uint64_t next_goal_id_{1};
  std::vector<double> goal_tolerance_rad_;  // per joint; < 0 = none
  std::vector<double> path_tolerance_rad_;  // per joint; <= 0 = none
  double goal_deadline_s_{0.0};
};

}  // namespace ari_social_sim::physics
