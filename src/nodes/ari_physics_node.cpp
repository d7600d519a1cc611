// ari_physics_node: ARI on Bullet (physics core) behind ARI's own ROS interfaces.
// Reads parameters, builds the core, wires topics, actions, services and tf, converts at the
// edges. Controllers, limits, odometry and head pointing are the core's; this file only times
// and publishes them.

#include <actionlib/server/action_server.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <memory>
#include <optional>

#include "ari_social_sim/FollowJointTrajectoryAction.h"
#include "ari_social_sim/JointTrajectoryControllerState.h"
#include "ari_social_sim/PointHeadAction.h"
#include "ari_social_sim/QueryTrajectoryState.h"
#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/physics/ari_physics.hpp"
#include "ari_social_sim/physics/physics_run_config.hpp"
#include "ari_social_sim/physics/point_head.hpp"
#include "ari_social_sim/physics/point_head_goal.hpp"
#include "ari_social_sim/world/scene.hpp"
#include "camera_interface.hpp"
#include "conversions/ari_base.hpp"
#include "conversions/joint_trajectory.hpp"
#include "conversions/transform.hpp"
#include "frames.hpp"
#include "renewing_tf_buffer.hpp"
#include "ros_params.hpp"

namespace ari_social_sim::nodes {
namespace {

// The torso RGB-D camera is a D435i; its IMU topic is realsense2_camera's unified one
// (docs/physics.md: ARI's own launch files name no IMU topic).
constexpr char kImuTopic[] = "/torso_front_camera/imu";
// JointTrajectoryController's action_monitor_rate (ari_robot's controller configuration).
constexpr double kActionMonitorRateHz = 20.0;
// PAL's head_action: success_angle_threshold (rad) and its default pointing frame.
constexpr double kPointingThresholdRad = 0.01;
constexpr char kDefaultPointingFrame[] = "head_front_camera_color_optical_frame";
// How long a point-head goal waits for tf to know its target frame, and how old the frame's
// newest transform may grow while the goal runs (wall and sim seconds): a goal on a person who
// left fails well within a second, and live frames (10-50 Hz) come far more often.
constexpr double kTfWaitS = 0.5;
// Covariance diagonal of mobile_base_controller's pose and twist (ari_robot's controller
// configuration).
constexpr double kOdomCovariance[6] = {0.001, 0.001, 1e6, 1e6, 1e6, 1000.0};

geometry_msgs::Quaternion quaternion_msg(const Eigen::Quaterniond& q) {
  geometry_msgs::Quaternion out;
  out.x = q.x();
  out.y = q.y();
  out.z = q.z();
  out.w = q.w();
  return out;
}

geometry_msgs::Pose pose_msg(const Eigen::Isometry3d& X) {
  geometry_msgs::Pose pose;
  pose.position.x = X.translation().x();
  pose.position.y = X.translation().y();
  pose.position.z = X.translation().z();
  pose.orientation = quaternion_msg(Eigen::Quaterniond(X.linear()));
  return pose;
}

Eigen::Isometry3d planar(const core::Pose2& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(pose.position.x(), pose.position.y(), 0.0);
  X.linear() = Eigen::AngleAxisd(pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

// The odom frame in the map as a localised robot knows it: the true planar base pose composed
// with the inverse of the wheel odometry. The wheels slip (a fast turn on the spot can cost a
// metre), and ARI's own localisation corrects for it; this stands in for that localisation,
// without its error.
core::Pose2 odom_in_map(const physics::AriPhysics& physics) {
  const Eigen::Isometry3d X_map_base = physics.frame_pose(kBaseFrame);
  const core::Pose2& base_in_odom = physics.odometry().pose();
  core::Pose2 odom;
  odom.theta = core::wrap_angle(std::atan2(X_map_base.linear()(1, 0), X_map_base.linear()(0, 0)) -
                                base_in_odom.theta);
  odom.position =
      X_map_base.translation().head<2>() - Eigen::Rotation2Dd(odom.theta) * base_in_odom.position;
  return odom;
}

void set_covariance(boost::array<double, 36>& covariance) {
  for (int i = 0; i < 6; ++i) {
    covariance[static_cast<size_t>(7 * i)] = kOdomCovariance[i];
  }
}

/// Sim time as the ROS graph sees it: the physics' own time plus where it started on the graph's
/// clock (0 when this node owns /clock; world_node's time at start-up when it follows it).
struct SimClock {
  const physics::AriPhysics* physics{nullptr};
  double origin_s{0.0};

  double now_s() const { return origin_s + physics->time_s(); }
  ros::Time now() const { return ros::Time(now_s()); }
  /// A ROS stamp in the physics' time; 0 (meaning "now") stays 0.
  double to_physics(const ros::Time& stamp) const {
    return stamp.isZero() ? 0.0 : std::max(1e-9, stamp.toSec() - origin_s);
  }
};

/// One joint trajectory controller's ROS face: /command, follow_joint_trajectory, /state,
/// query_state, with the names and semantics of ros_controllers.
class ControllerInterface {
 public:
  using Server = actionlib::ActionServer<FollowJointTrajectoryAction>;

  ControllerInterface(ros::NodeHandle& nh, physics::TrajectoryController& controller,
                      physics::AriPhysics& physics, const SimClock& clock)
      : controller_(controller),
        physics_(physics),
        clock_(clock),
        server_(nh, "/" + controller.spec().name + "/follow_joint_trajectory", false) {
    const std::string ns = "/" + controller.spec().name;
    command_sub_ = nh.subscribe(ns + "/command", 1, &ControllerInterface::on_command, this);
    state_pub_ = nh.advertise<JointTrajectoryControllerState>(ns + "/state", 10);
    query_ = nh.advertiseService(ns + "/query_state", &ControllerInterface::on_query, this);
    server_.registerGoalCallback([this](Server::GoalHandle goal) { on_goal(goal); });
    server_.registerCancelCallback([this](Server::GoalHandle goal) { on_cancel(goal); });
    server_.start();
  }

  void publish_state() {
    JointTrajectoryControllerState state = make_state();
    state_pub_.publish(state);
  }

  /// Reports the active goal's outcome once the core has judged it; feedback at the action
  /// monitor rate.
  void update_goal() {
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

 private:
  JointTrajectoryControllerState make_state() const {
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

  physics::TrajectoryRequest timed(physics::TrajectoryRequest request) const {
    request.start_time_s =
        request.start_time_s > 0.0 ? clock_.to_physics(ros::Time(request.start_time_s)) : 0.0;
    return request;
  }

  void on_command(const trajectory_msgs::JointTrajectory& trajectory) {
    try {
      controller_.follow(timed(from_msg(trajectory)), physics_.time_s(), false);
    } catch (const core::Error& e) {
      ROS_WARN("%s/command ignored: %s", controller_.spec().name.c_str(), e.what());
    }
  }

  void on_goal(Server::GoalHandle goal) {
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

  void on_cancel(Server::GoalHandle goal) {
    if (active_ && *active_ == goal) {
      controller_.cancel(active_id_, physics_.time_s());
      active_->setCanceled(FollowJointTrajectoryResult(), "canceled");
      active_.reset();
    }
  }

  bool on_query(QueryTrajectoryState::Request& request, QueryTrajectoryState::Response& response) {
    const physics::JointSetpoint state =
        controller_.sample(std::max(0.0, request.time.toSec() - clock_.origin_s));
    response.name = controller_.spec().joints;
    response.position = state.positions;
    response.velocity = state.velocities;
    response.acceleration = state.accelerations;
    return true;
  }

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
                     const RenewingTfBuffer& tf)
      : physics_(physics),
        clock_(clock),
        tf_(tf),
        solver_(physics.model()),
        head_(physics.controller("head_controller")),
        server_(nh, "/head_controller/point_head_action", false) {
    server_.registerGoalCallback([this](Server::GoalHandle goal) { on_goal(goal); });
    server_.registerCancelCallback([this](Server::GoalHandle goal) { on_cancel(goal); });
    server_.start();
  }

  void update_goal() {
    if (!active_ || (is_tf_frame(goal_.target_frame) && !target_still_in_tf()) || !moving_) {
      return;
    }
    const physics::GoalOutcome& outcome = head_.goal();
    PointHeadFeedback feedback;
    feedback.pointing_angle_error = error_now();
    active_->publishFeedback(feedback);
    if (outcome.goal_id != head_goal_id_ || outcome.state == physics::GoalState::kPreempted) {
      active_->setCanceled(PointHeadResult(), "preempted by another head command");
      active_.reset();
    } else if (outcome.state == physics::GoalState::kAborted) {
      active_->setAborted(PointHeadResult(), outcome.message);
      active_.reset();
    } else if (outcome.state == physics::GoalState::kSucceeded &&
               feedback.pointing_angle_error < kPointingThresholdRad) {
      active_->setSucceeded();
      active_.reset();
    } else if (outcome.state == physics::GoalState::kSucceeded &&
               clock_.now_s() > settle_deadline_s_) {
      active_->setAborted(PointHeadResult(), "the head stopped " +
                                                 std::to_string(feedback.pointing_angle_error) +
                                                 " rad from the target");
      active_.reset();
    }
  }

 private:
  /// The head's trajectory for a goal, with what it aims at.
  struct HeadMove {
    physics::TrajectoryRequest trajectory;
    double duration_s{0.0};
    Eigen::Vector3d target_base{Eigen::Vector3d::Zero()};
  };

  static physics::PointHeadGoal goal_of(const PointHeadGoal& msg) {
    physics::PointHeadGoal goal;
    goal.target_frame =
        msg.target.header.frame_id.empty() ? std::string(kBaseFrame) : msg.target.header.frame_id;
    goal.target_point = {msg.target.point.x, msg.target.point.y, msg.target.point.z};
    goal.pointing_axis = {msg.pointing_axis.x, msg.pointing_axis.y, msg.pointing_axis.z};
    goal.pointing_frame = msg.pointing_frame.empty() ? kDefaultPointingFrame : msg.pointing_frame;
    goal.min_duration_s = msg.min_duration.toSec();
    goal.max_velocity_rps = msg.max_velocity;
    return goal;
  }

  static double wall_now_s() { return ros::WallTime::now().toSec(); }

  std::unordered_map<std::string, double> joint_positions() const {
    std::unordered_map<std::string, double> q;
    const std::vector<double> positions = physics_.joint_positions();
    for (size_t j = 0; j < positions.size(); ++j) {
      q[physics_.joint_names()[j]] = positions[j];
    }
    return q;
  }

  double error_now() const {
    return solver_.pointing_error(target_base_, goal_.pointing_axis, goal_.pointing_frame,
                                  joint_positions());
  }

  double max_velocity_rps(const char* joint) const {
    return physics_.model().joint(joint).max_velocity_rps;
  }

  // ARI's own frames, map and odom come from the physics; any other frame through tf.
  bool is_tf_frame(const std::string& frame) const {
    return frame != kMapFrame && frame != kOdomFrame && physics_.model().link_index(frame) < 0;
  }

  // The newest transform from `frame` to base_footprint, without waiting; nothing (and the
  // reason in `error`) when tf cannot give one.
  std::optional<geometry_msgs::TransformStamped> latest_tf(const std::string& frame,
                                                           std::string* error) const {
    try {
      return tf_.buffer().lookupTransform(kBaseFrame, frame, ros::Time(0));
    } catch (const tf2::TransformException& e) {
      *error = e.what();
      return std::nullopt;
    }
  }

  // The target in base_footprint; nothing while tf does not know its frame.
  std::optional<Eigen::Vector3d> target_in_base(const physics::PointHeadGoal& goal) const {
    if (!is_tf_frame(goal.target_frame)) {
      const Eigen::Isometry3d X_map_frame =
          goal.target_frame == kMapFrame    ? Eigen::Isometry3d::Identity()
          : goal.target_frame == kOdomFrame ? planar(odom_in_map(physics_))
                                            : physics_.frame_pose(goal.target_frame);
      return physics_.frame_pose(kBaseFrame).inverse() * X_map_frame * goal.target_point;
    }
    std::string error;
    const std::optional<geometry_msgs::TransformStamped> t = latest_tf(goal.target_frame, &error);
    if (!t) {
      return std::nullopt;
    }
    return isometry_of(t->transform) * goal.target_point;
  }

  // Pan and tilt for the target, timed as PAL's head_action times them; throws core::RequestError
  // for a target out of reach or a move too slow.
  HeadMove plan_move(const physics::PointHeadGoal& goal, const Eigen::Vector3d& target_base) const {
    const std::unordered_map<std::string, double> q = joint_positions();
    const physics::HeadAim aim =
        solver_.solve(target_base, goal.pointing_axis, goal.pointing_frame, q);
    if (aim.error_rad > kPointingThresholdRad) {
      throw core::RequestError("target out of the head's reach: the pan and tilt limits leave " +
                               std::to_string(aim.error_rad) + " rad of error");
    }
    HeadMove move;
    move.target_base = target_base;
    move.duration_s = physics::point_head_duration(
        goal, std::abs(aim.pan_rad - q.at("head_1_joint")),
        std::abs(aim.tilt_rad - q.at("head_2_joint")), max_velocity_rps("head_1_joint"),
        max_velocity_rps("head_2_joint"));
    move.trajectory.joint_names = {"head_1_joint", "head_2_joint"};
    move.trajectory.points = {{{aim.pan_rad, aim.tilt_rad}, {0.0, 0.0}, {}, move.duration_s}};
    return move;
  }

  void start_move(const HeadMove& move) {
    try {
      head_goal_id_ = head_.follow(move.trajectory, physics_.time_s(), true);
    } catch (const core::Error& e) {
      abort(e.what());
      return;
    }
    target_base_ = move.target_base;
    settle_deadline_s_ = clock_.now_s() + move.duration_s + head_.spec().goal_time_s;
    moving_ = true;
  }

  void abort(const std::string& message) {
    if (moving_) {
      head_.cancel(head_goal_id_, physics_.time_s());
    }
    ROS_WARN("point_head_action: %s", message.c_str());
    active_->setAborted(PointHeadResult(), message);
    active_.reset();
  }

  // Watches the active goal's tf frame: starts the move once the frame is there, aborts the
  // goal when it never comes or stops coming. True while the goal goes on with its frame.
  bool target_still_in_tf() {
    std::string error;
    const std::string& frame = goal_.target_frame;
    const std::optional<geometry_msgs::TransformStamped> t = latest_tf(frame, &error);
    const std::optional<double> stamp_s =
        t ? std::optional<double>(t->header.stamp.toSec()) : std::nullopt;
    switch (watch_.look(stamp_s, wall_now_s(), clock_.now_s())) {
      case physics::FrameWatch::Status::kWaiting:
        return false;
      case physics::FrameWatch::Status::kNeverSeen:
        abort(
            core::format_text("target.header.frame_id: no transform from '%s' to %s within "
                              "%.1f s (wall clock): %s",
                              frame.c_str(), kBaseFrame, kTfWaitS, error.c_str()));
        return false;
      case physics::FrameWatch::Status::kStale:
        abort(core::format_text(
            "target.header.frame_id: '%s' left tf: its newest transform is %.2f s old (sim "
            "time) and none came for %.1f s (wall clock)",
            frame.c_str(), clock_.now_s() - watch_.newest_stamp_s().value_or(0.0), kTfWaitS));
        return false;
      case physics::FrameWatch::Status::kFresh:
        break;
    }
    if (!moving_) {
      try {
        start_move(plan_move(goal_, isometry_of(t->transform) * goal_.target_point));
      } catch (const core::Error& e) {
        abort(e.what());
      }
    }
    return active_.has_value();
  }

  void on_goal(Server::GoalHandle goal) {
    const physics::PointHeadGoal request = goal_of(*goal.getGoal());
    std::optional<HeadMove> move;
    try {
      physics::check_point_head_goal(
          request, std::min(max_velocity_rps("head_1_joint"), max_velocity_rps("head_2_joint")));
      if (const std::optional<Eigen::Vector3d> target = target_in_base(request)) {
        move = plan_move(request, *target);
      }
    } catch (const core::Error& e) {
      ROS_WARN("point_head_action: %s", e.what());
      goal.setRejected(PointHeadResult(), e.what());
      return;
    }
    if (active_) {
      if (moving_) {
        head_.cancel(head_goal_id_, physics_.time_s());
      }
      active_->setCanceled(PointHeadResult(), "preempted by a newer goal");
    }
    goal.setAccepted();
    active_ = goal;
    goal_ = request;
    moving_ = false;
    watch_.start(wall_now_s());
    if (move) {
      start_move(*move);
    }
  }

  void on_cancel(Server::GoalHandle goal) {
    if (active_ && *active_ == goal) {
      if (moving_) {
        head_.cancel(head_goal_id_, physics_.time_s());
      }
      active_->setCanceled();
      active_.reset();
    }
  }

  physics::AriPhysics& physics_;
  const SimClock& clock_;
  const RenewingTfBuffer& tf_;
  physics::PointHeadSolver solver_;
  physics::TrajectoryController& head_;
  Server server_;
  std::optional<Server::GoalHandle> active_;
  physics::PointHeadGoal goal_;  // the active goal's, defaults filled in
  bool moving_{false};           // the head's trajectory for the active goal was sent
  physics::FrameWatch watch_{kTfWaitS};
  uint64_t head_goal_id_{0};
  double settle_deadline_s_{0.0};
  Eigen::Vector3d target_base_{Eigen::Vector3d::Zero()};
};

class PhysicsNode {
 public:
  /// Throws what CameraInterface throws (bad camera or mapping parameters, no OpenGL context).
  PhysicsNode(const physics::PhysicsRunConfig& config, const model::WorldDescription& world,
              std::unique_ptr<physics::AriPhysics> physics)
      : config_(config), physics_(std::move(physics)) {
    clock_.physics = physics_.get();
    if (config_.cameras_enabled) {
      cameras_ = std::make_unique<CameraInterface>(nh_, config_, world, *physics_);
    }
    if (config_.clock == physics::ClockSource::kOwn) {
      clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    }
    joint_state_pub_ = nh_.advertise<sensor_msgs::JointState>("/joint_states", 10);
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("/mobile_base_controller/odom", 10);
    ground_truth_pub_ = nh_.advertise<nav_msgs::Odometry>("/ground_truth_odom", 10);
    imu_pub_ = nh_.advertise<sensor_msgs::Imu>(kImuTopic, 10);
    cmd_vel_sub_ =
        nh_.subscribe("/mobile_base_controller/cmd_vel", 1, &PhysicsNode::on_cmd_vel, this);
    world_state_sub_ = nh_.subscribe("/sim/world_state", 1, &PhysicsNode::on_world_state, this);
    for (const auto& controller : physics_->controllers()) {
      controllers_.push_back(
          std::make_unique<ControllerInterface>(nh_, *controller, *physics_, clock_));
    }
    point_head_ = std::make_unique<PointHeadInterface>(nh_, *physics_, clock_, tf_);
  }

  void run() {
    if (config_.clock == physics::ClockSource::kWorld) {
      run_on_world_clock();
    } else {
      run_on_own_clock();
    }
  }

 private:
  // Own clock: advance one /clock tick at a time, paced at the real-time factor.
  void run_on_own_clock() {
    const double tick_s = 1.0 / kClockRateHz;
    ros::WallTime start = ros::WallTime::now();
    const double start_sim_s = clock_.now_s();
    publish_clock();
    while (ros::ok()) {
      ros::spinOnce();
      tf_.renew_if_stale();
      advance_to(clock_.now_s() + tick_s);
      publish_clock();
      if (config_.real_time_factor > 0.0) {
        const ros::WallTime due =
            start + ros::WallDuration((clock_.now_s() - start_sim_s) / config_.real_time_factor);
        const ros::WallTime now = ros::WallTime::now();
        if (due > now) {
          (due - now).sleep();
        }
      }
    }
  }

  // World clock: step up to each /clock world_node publishes.
  void run_on_world_clock() {
    bool anchored = false;
    while (ros::ok()) {
      ros::spinOnce();
      tf_.renew_if_stale();
      const double now_s = ros::Time::now().toSec();
      if (now_s <= 0.0) {
        ros::WallDuration(0.001).sleep();
        continue;
      }
      if (!anchored || now_s < clock_.now_s() - 1.0) {
        // First tick, or the world was reset: line the physics' time up with the world's.
        clock_.origin_s = now_s - physics_->time_s();
        anchored = true;
      }
      if (clock_.now_s() + 0.5 * physics_->config().step_s < now_s) {
        advance_to(now_s);
      } else {
        ros::WallDuration(0.0005).sleep();
      }
    }
  }

  void advance_to(double target_s) {
    while (clock_.now_s() + 0.5 * physics_->config().step_s < target_s && ros::ok()) {
      physics_->step();
      publish_due();
    }
    for (auto& controller : controllers_) {
      controller->update_goal();
    }
    point_head_->update_goal();
  }

  void publish_clock() {
    rosgraph_msgs::Clock clock;
    clock.clock = clock_.now();
    clock_pub_.publish(clock);
  }

  // Everything whose period has come, stamped with the sim time of this step.
  void publish_due() {
    const double now_s = clock_.now_s();
    const ros::Time stamp = clock_.now();
    if (now_s + 1e-9 >= next_publish_s_) {
      next_publish_s_ = now_s + 1.0 / config_.publish_rate_hz;
      publish_joint_states(stamp);
      publish_odometry(stamp);
      for (auto& controller : controllers_) {
        controller->publish_state();
      }
    }
    if (cameras_) {
      cameras_->update(stamp);
    }
    if (now_s + 1e-9 >= next_ground_truth_s_) {
      next_ground_truth_s_ = now_s + 1.0 / config_.ground_truth_rate_hz;
      publish_ground_truth(stamp);
    }
    if (physics_->imu_reading_count() != published_imu_count_) {
      published_imu_count_ = physics_->imu_reading_count();
      publish_imu(stamp);
    }
    const uint64_t clamps = physics_->diagnostics().clamped_base_commands;
    if (clamps > reported_clamps_) {
      ROS_WARN_THROTTLE(5.0, "cmd_vel beyond ARI's limits was scaled down (%lu so far)",
                        static_cast<unsigned long>(clamps));
      reported_clamps_ = clamps;
    }
    if (physics_->diagnostics().nan_resets > 0) {
      ROS_ERROR_THROTTLE(5.0, "physics blew up and was reset %lu times",
                         static_cast<unsigned long>(physics_->diagnostics().nan_resets));
    }
  }

  void publish_joint_states(const ros::Time& stamp) {
    sensor_msgs::JointState state;
    state.header.stamp = stamp;
    state.name = physics_->joint_names();
    state.position = physics_->joint_positions();
    state.velocity = physics_->joint_velocities();
    state.effort = physics_->joint_efforts();
    joint_state_pub_.publish(state);
  }

  void publish_odometry(const ros::Time& stamp) {
    const physics::WheelOdometry& odometry = physics_->odometry();
    nav_msgs::Odometry odom;
    odom.header.stamp = stamp;
    odom.header.frame_id = kOdomFrame;
    odom.child_frame_id = kBaseFrame;
    odom.pose.pose = pose_msg(planar(odometry.pose()));
    odom.twist.twist.linear.x = odometry.linear_mps();
    odom.twist.twist.angular.z = odometry.angular_rps();
    set_covariance(odom.pose.covariance);
    set_covariance(odom.twist.covariance);
    odom_pub_.publish(odom);

    tf_broadcaster_.sendTransform({odom_to_base(odometry.pose(), stamp.toSec()),
                                   map_to_odom(stamp.toSec(), odom_in_map(*physics_))});
  }

  void publish_ground_truth(const ros::Time& stamp) {
    nav_msgs::Odometry truth;
    truth.header.stamp = stamp;
    truth.header.frame_id = kMapFrame;
    truth.child_frame_id = kBaseFrame;
    truth.pose.pose = pose_msg(physics_->frame_pose(kBaseFrame));
    truth.twist.twist.linear.x = physics_->base_linear_mps();
    truth.twist.twist.angular.z = physics_->base_angular_rps();
    ground_truth_pub_.publish(truth);
  }

  void publish_imu(const ros::Time& stamp) {
    const physics::ImuReading& reading = physics_->imu();
    sensor_msgs::Imu imu;
    imu.header.stamp = stamp;
    imu.header.frame_id = physics::AriPhysics::kImuFrame;
    imu.orientation_covariance[0] = -1.0;  // no orientation estimate, as the D435i's
    imu.angular_velocity.x = reading.angular_velocity_rps.x();
    imu.angular_velocity.y = reading.angular_velocity_rps.y();
    imu.angular_velocity.z = reading.angular_velocity_rps.z();
    imu.linear_acceleration.x = reading.linear_acceleration_mps2.x();
    imu.linear_acceleration.y = reading.linear_acceleration_mps2.y();
    imu.linear_acceleration.z = reading.linear_acceleration_mps2.z();
    const physics::ImuNoise& noise = physics_->config().imu_noise;
    for (int i = 0; i < 3; ++i) {
      imu.angular_velocity_covariance[static_cast<size_t>(4 * i)] =
          noise.gyro_std_rps * noise.gyro_std_rps;
      imu.linear_acceleration_covariance[static_cast<size_t>(4 * i)] =
          noise.accel_std_mps2 * noise.accel_std_mps2;
    }
    imu_pub_.publish(imu);
  }

  void on_cmd_vel(const geometry_msgs::Twist& twist) {
    if (!std::isfinite(twist.linear.x) || !std::isfinite(twist.angular.z)) {
      ROS_WARN_THROTTLE(5.0, "cmd_vel ignored: values must be finite");
      return;
    }
    physics_->command_base(twist.linear.x, twist.angular.z);
  }

  void on_world_state(const WorldState& state) {
    std::vector<physics::PersonState> people;
    for (const HumanState& human : state.humans) {
      physics::PersonState person;
      person.id = human.id;
      person.pose = {{human.pose.x, human.pose.y}, human.pose.theta};
      person.velocity_mps = {human.velocity.linear.x, human.velocity.linear.y};
      person.angular_velocity_rps = human.velocity.angular.z;
      person.face_yaw_rad = human.gaze.direction;
      person.age_years = human.age;
      person.gender = static_cast<model::Gender>(human.gender);
      person.mask = human.mask;
      person.speaking = human.speech.is_speaking;
      people.push_back(person);
    }
    physics_->set_people(people);
  }

  // /clock period when this node owns time: fine enough for actionlib and tf, few enough
  // messages at 20x real time.
  static constexpr double kClockRateHz = 200.0;

  physics::PhysicsRunConfig config_;
  std::unique_ptr<physics::AriPhysics> physics_;
  SimClock clock_;
  double next_publish_s_{0.0};
  double next_ground_truth_s_{0.0};
  uint64_t published_imu_count_{0};
  uint64_t reported_clamps_{0};

  ros::NodeHandle nh_;
  ros::Publisher clock_pub_, joint_state_pub_, odom_pub_, ground_truth_pub_, imu_pub_;
  ros::Subscriber cmd_vel_sub_, world_state_sub_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  // Point-head targets may be people's frames, which come and go with perception's ids.
  RenewingTfBuffer tf_;
  std::vector<std::unique_ptr<ControllerInterface>> controllers_;
  std::unique_ptr<PointHeadInterface> point_head_;
  std::unique_ptr<CameraInterface> cameras_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  ros::init(argc, argv, "ari_physics_node");
  ros::NodeHandle private_handle("~");
  physics::PhysicsRunConfig config;
  std::unique_ptr<physics::RobotModel> model;
  std::unique_ptr<nodes::PhysicsNode> node;
  try {
    config = physics::PhysicsRunConfig::from_yaml(nodes::read_private_params(private_handle));
    const std::string package = ros::package::getPath("ari_social_sim");
    model = std::make_unique<physics::RobotModel>(physics::RobotModel::from_urdf_file(
        config.urdf.empty() ? package + "/urdf/ari.urdf" : config.urdf));
    model::WorldDescription world_description;
    std::unique_ptr<physics::AriPhysics> simulation;
    core::Pose2 start;
    if (!config.scene.empty()) {
      const world::Scene scene = world::load_scene_file(config.scene);
      if (!scene.ari) {
        throw core::ConfigError(config.scene + ": ari: the scene has no ARI to simulate");
      }
      world_description = scene.world;
      start = scene.ari->pose;
    } else {
      world_description = model::load_world_file(
          config.world.empty() ? package + "/worlds/room_6x6.yaml" : config.world);
      start = config.start_pose().value_or(
          core::Pose2{world_description.origin + 0.5 * world_description.size, 0.0});
    }
    simulation =
        std::make_unique<physics::AriPhysics>(*model, world_description, start, config.physics);
    ROS_INFO("ari_physics_node: world %s, ARI at (%.2f, %.2f, %.2f rad), step %.4f s, clock %s",
             world_description.name.c_str(), start.position.x(), start.position.y(), start.theta,
             config.physics.step_s,
             config.clock == physics::ClockSource::kOwn ? "own" : "world_node's");
    node = std::make_unique<nodes::PhysicsNode>(config, world_description, std::move(simulation));
  } catch (const core::Error& e) {
    ROS_FATAL("%s%s", e.what(),
              dynamic_cast<const physics::RenderError*>(&e) != nullptr
                  ? " (run with _cameras_enabled:=false to simulate without cameras)"
                  : "");
    return 2;
  }
  node->run();
  return 0;
}
