// social_mpc_node: ARI's social navigation (SocialMPC) as a ROS node. Reads parameters into the
// navigation config, builds the navigator on /map, turns what perception reports (/humans/...
// and tf) into the scene it plans with, serves move_base, /move_base_simple/goal and
// /social_mpc/approach, and publishes ARI's commands, the plan and markers. No ground truth.

#include <actionlib/server/action_server.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "ari_social_sim/ApproachAction.h"
#include "ari_social_sim/Group.h"
#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/navigation/perception_report.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"
#include "conversions/navigation_msgs.hpp"
#include "conversions/world_state.hpp"
#include "input_counters.hpp"
#include "perceived_persons.hpp"
#include "renewing_tf_buffer.hpp"
#include "ros_params.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr char kMapFrame[] = "map";
constexpr char kBaseFrame[] = "base_footprint";
constexpr char kHeadPanJoint[] = "head_1_joint";
constexpr char kHeadTiltJoint[] = "head_2_joint";
constexpr char kOdomTopic[] = "/mobile_base_controller/odom";
// How long (s of sim time) an approach goal naming someone not perceived yet waits for them
// before it is rejected: a client may have learnt the id a moment before this node receives the
// person's body (its latched body_id and first frames).
constexpr double kTargetWait_s = 2.0;

using MoveBaseServer = actionlib::ActionServer<move_base_msgs::MoveBaseAction>;
using ApproachServer = actionlib::ActionServer<ApproachAction>;

class SocialMpcNode {
 public:
  explicit SocialMpcNode(const navigation::NavigationConfig& config)
      : config_(config),
        tracker_(config.scene),
        persons_(nh_),
        move_base_(nh_, "move_base", false),
        approach_(nh_, "/social_mpc/approach", false) {
    cmd_vel_pub_ = nh_.advertise<geometry_msgs::Twist>("/mobile_base_controller/cmd_vel", 1);
    head_pub_ = nh_.advertise<trajectory_msgs::JointTrajectory>("/head_controller/command", 1);
    plan_pub_ = nh_.advertise<nav_msgs::Path>("/social_mpc/plan", 1);
    markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("/social_mpc/markers", 1);
    status_pub_ = nh_.advertise<std_msgs::String>("/social_mpc/status", 1, /*latch=*/true);
    diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10);
    map_sub_ = nh_.subscribe("/map", 1, &SocialMpcNode::on_map, this);
    odom_sub_ = nh_.subscribe(kOdomTopic, 1, &SocialMpcNode::on_odom, this);
    joints_sub_ = nh_.subscribe("/joint_states", 1, &SocialMpcNode::on_joints, this);
    groups_sub_ = nh_.subscribe("/humans/interactions/groups", 20, &SocialMpcNode::on_group, this);
    simple_goal_sub_ =
        nh_.subscribe("/move_base_simple/goal", 1, &SocialMpcNode::on_simple_goal, this);
    move_base_.registerGoalCallback([this](MoveBaseServer::GoalHandle h) { on_move_base(h); });
    move_base_.registerCancelCallback(
        [this](MoveBaseServer::GoalHandle h) { on_cancel(h.getGoalID()); });
    approach_.registerGoalCallback([this](ApproachServer::GoalHandle h) { on_approach(h); });
    approach_.registerCancelCallback(
        [this](ApproachServer::GoalHandle h) { on_cancel(h.getGoalID()); });
    move_base_.start();
    approach_.start();
    timer_ = nh_.createTimer(ros::Duration(1.0 / config_.navigator.rate_hz),
                             &SocialMpcNode::on_timer, this);
    publish_status("idle");
  }

 private:
  // What the current goal came from, so that its end reaches the right client.
  struct ActiveGoal {
    std::optional<MoveBaseServer::GoalHandle> move_base;
    std::optional<ApproachServer::GoalHandle> approach;
    std::string id;  // actionlib goal id, empty for /move_base_simple/goal
  };

  // ---- inputs ----------------------------------------------------------------------------
  void on_map(const nav_msgs::OccupancyGrid& msg) {
    if (const std::optional<InputProblem> problem = input_problem(msg)) {
      inputs_.drop("/map", problem->field, problem->what);
      return;
    }
    if (active_) {
      finish(navigation::NavigationState::kAborted, "the map changed while navigating");
    }
    navigator_ = std::make_unique<navigation::Navigator>(config_, from_msg(msg));
    ROS_INFO("social_mpc_node: map %ux%u at %.3f m", msg.info.width, msg.info.height,
             msg.info.resolution);
  }

  void on_odom(const nav_msgs::Odometry& msg) {
    const bool linear_ok =
        inputs_.finite(kOdomTopic, "twist.twist.linear.x", msg.twist.twist.linear.x);
    const bool angular_ok =
        inputs_.finite(kOdomTopic, "twist.twist.angular.z", msg.twist.twist.angular.z);
    if (linear_ok && angular_ok) {
      linear_mps_ = msg.twist.twist.linear.x;
      angular_rps_ = msg.twist.twist.angular.z;
    }
  }

  void on_joints(const sensor_msgs::JointState& msg) {
    const auto it = std::find(msg.name.begin(), msg.name.end(), kHeadPanJoint);
    if (it == msg.name.end()) {
      return;
    }
    const size_t i = static_cast<size_t>(it - msg.name.begin());
    if (i < msg.position.size() &&
        inputs_.finite("/joint_states", "position[head_1_joint]", msg.position[i])) {
      pan_rad_ = msg.position[i];
    }
    if (i < msg.velocity.size() &&
        inputs_.finite("/joint_states", "velocity[head_1_joint]", msg.velocity[i])) {
      pan_rps_ = msg.velocity[i];
    }
  }

  // Kept for the next cycle, which observes them with the persons (observe_perception).
  void on_group(const Group& msg) {
    received_groups_.push_back({msg.group_id, msg.header.stamp.toSec(), msg.members});
  }

  // What perception reported since the last call into the tracker (navigation::observe): the
  // persons tracked now, each at their body frame in the map from tf, and the groups received.
  void observe_perception() {
    navigation::PerceptionReport report{persons_.tracked(), std::move(received_groups_)};
    received_groups_.clear();
    navigation::observe(
        tracker_, report,
        [this](const std::string& body_id) {
          return body_placement(tf_.buffer(), kMapFrame, body_id);
        },
        ros::Time::now().toSec());
  }

  std::optional<navigation::RobotObservation> observe_robot() const {
    geometry_msgs::TransformStamped t;
    try {
      t = tf_.buffer().lookupTransform(kMapFrame, kBaseFrame, ros::Time(0));
    } catch (const tf2::TransformException&) {
      return std::nullopt;
    }
    navigation::RobotObservation robot;
    robot.pose.position = {t.transform.translation.x, t.transform.translation.y};
    robot.pose.theta = tf2::getYaw(t.transform.rotation);
    robot.linear_mps = linear_mps_;
    robot.angular_rps = angular_rps_;
    robot.pan_rad = pan_rad_;
    robot.pan_rps = pan_rps_;
    return robot;
  }

  // ---- goals ---------------------------------------------------------------------------
  // Starts a target; throws core::Error with the reason it cannot be pursued.
  void start(const navigation::NavigationTarget& target) {
    if (!navigator_) {
      throw core::RequestError("no map received on /map yet");
    }
    const std::optional<navigation::RobotObservation> robot = observe_robot();
    if (!robot) {
      throw core::RequestError(std::string("no transform from ") + kMapFrame + " to " + kBaseFrame +
                               " yet");
    }
    observe_perception();
    const double now = ros::Time::now().toSec();
    navigator_->start(target, tracker_.scene(now), *robot, now);
  }

  // Replaces the active goal, telling its client it was preempted.
  void replace_active(ActiveGoal next) {
    if (active_) {
      end_active(actionlib_msgs::GoalStatus::PREEMPTED, "preempted by a new goal");
    }
    active_ = std::move(next);
  }

  // The goal pose in the map frame, checked field by field (navigation::planar_goal), turned
  // into map through tf if it is in another frame, and inside the map once there is one; throws
  // core::RequestError naming the field. `field` prefixes field names: "target_pose." for
  // move_base, "" for /move_base_simple/goal.
  core::Pose2 goal_in_map(const geometry_msgs::PoseStamped& goal, const std::string& field) {
    const core::Pose2 pose = navigation::planar_goal(goal_request_of(goal), field);
    core::Pose2 in_map = pose;
    const std::string& frame = goal.header.frame_id;
    if (!navigation::names_map_frame(frame)) {
      geometry_msgs::TransformStamped t;
      try {
        t = tf_.buffer().lookupTransform(kMapFrame, frame, ros::Time(0));
      } catch (const tf2::TransformException& e) {
        throw core::RequestError(field + "header.frame_id: no transform from '" + frame +
                                 "' to map (" + e.what() + ")");
      }
      core::Pose2 frame_in_map;
      frame_in_map.position = {t.transform.translation.x, t.transform.translation.y};
      frame_in_map.theta = tf2::getYaw(t.transform.rotation);
      in_map.position = frame_in_map.transform(pose.position);
      in_map.theta = core::wrap_angle(frame_in_map.theta + pose.theta);
    }
    // Without a map yet the goal is accepted and then aborted with that reason (start()).
    if (navigator_) {
      navigation::check_inside_map(in_map, navigation::MapBounds::of(navigator_->sdf()),
                                   field + "pose.position");
    }
    return in_map;
  }

  // Accepts a goal whose request is well formed and starts it; a goal that cannot be reached
  // (nothing to plan on yet, no free place, no path) is aborted with the reason, as move_base
  // aborts a goal it finds no plan for.
  template <class Handle, class Result>
  void accept_and_start(Handle handle, const navigation::NavigationTarget& target, Result result,
                        ActiveGoal active) {
    handle.setAccepted();
    try {
      start(target);
    } catch (const core::Error& e) {
      ROS_WARN("goal aborted: %s", e.what());
      handle.setAborted(with_reason(result, e.what()), e.what());
      return;
    }
    replace_active(std::move(active));
    publish_status("pursuing " + navigation::describe(target));
  }

  static move_base_msgs::MoveBaseResult with_reason(move_base_msgs::MoveBaseResult result,
                                                    const std::string&) {
    return result;
  }
  static ApproachResult with_reason(ApproachResult result, const std::string& reason) {
    result.reason = reason;
    return result;
  }

  void on_move_base(MoveBaseServer::GoalHandle handle) {
    core::Pose2 pose;
    try {
      pose = goal_in_map(handle.getGoal()->target_pose, "target_pose.");
    } catch (const core::Error& e) {
      ROS_WARN("move_base goal rejected: %s", e.what());
      handle.setRejected(move_base_msgs::MoveBaseResult(), e.what());
      return;
    }
    accept_and_start(handle, navigation::PoseTarget{pose}, move_base_msgs::MoveBaseResult(),
                     {handle, std::nullopt, handle.getGoalID().id});
  }

  // The same checks as move_base; with no result channel, a refusal is a warning and the status.
  void on_simple_goal(const geometry_msgs::PoseStamped& goal) {
    try {
      start(navigation::PoseTarget{goal_in_map(goal, "")});
    } catch (const core::Error& e) {
      ROS_WARN("/move_base_simple/goal ignored: %s", e.what());
      publish_status(std::string("goal ignored: ") + e.what());
      return;
    }
    replace_active({std::nullopt, std::nullopt, ""});
    publish_status("pursuing /move_base_simple/goal");
  }

  // An approach goal naming an id perception does not report is rejected with the reason.
  void on_approach(ApproachServer::GoalHandle handle) {
    const ApproachGoalConstPtr goal = handle.getGoal();
    std::optional<navigation::NavigationTarget> target;
    std::string problem;
    switch (goal->target_type) {
      case ApproachGoal::TARGET_PERSON:
        target = navigation::PersonTarget{goal->target_id};
        break;
      case ApproachGoal::TARGET_GROUP:
        target = navigation::GroupTarget{goal->target_id};
        break;
      case ApproachGoal::TARGET_GROUP_OF_PERSON:
        target = navigation::GroupOfPersonTarget{goal->target_id};
        break;
      default:
        problem =
            "target_type: expected TARGET_PERSON (0), TARGET_GROUP (1) or "
            "TARGET_GROUP_OF_PERSON (2), got " +
            std::to_string(goal->target_type);
    }
    if (problem.empty()) {
      try {
        navigation::check_target_id(goal->target_id, "target_id");
      } catch (const core::RequestError& e) {
        problem = e.what();
      }
    }
    if (!problem.empty()) {
      reject(handle, problem);
      return;
    }
    if (waiting_) {
      reject(waiting_->handle, "preempted by a new goal before its target was perceived");
    }
    waiting_ = WaitingApproach{handle, *target, ros::Time::now().toSec() + kTargetWait_s};
    observe_perception();
    start_waiting_approach();
  }

  void reject(ApproachServer::GoalHandle handle, const std::string& problem) {
    ROS_WARN("approach goal rejected: %s", problem.c_str());
    handle.setRejected(with_reason(ApproachResult(), problem), problem);
  }

  // Starts the waiting approach once its target is perceived, or rejects it with the reason
  // once it has waited kTargetWait_s; it stays pending meanwhile. People must be observed first.
  void start_waiting_approach() {
    const double now = ros::Time::now().toSec();
    const std::string problem =
        navigation::unknown_target_reason(waiting_->target, tracker_.scene(now));
    if (problem.empty()) {
      ApproachServer::GoalHandle handle = waiting_->handle;
      const navigation::NavigationTarget target = waiting_->target;
      waiting_.reset();
      accept_and_start(handle, target, ApproachResult(),
                       {std::nullopt, handle, handle.getGoalID().id});
    } else if (now >= waiting_->until_s) {
      reject(waiting_->handle, problem);
      waiting_.reset();
    }
  }

  void on_cancel(const actionlib_msgs::GoalID& id) {
    if (waiting_ && waiting_->handle.getGoalID().id == id.id) {
      waiting_->handle.setCanceled(with_reason(ApproachResult(), "canceled by the client"));
      waiting_.reset();
    }
    if (active_ && active_->id == id.id) {
      end_active(actionlib_msgs::GoalStatus::PREEMPTED, "canceled by the client");
      if (navigator_) {
        navigator_->cancel();
      }
      stop();
    }
  }

  // Ends the active goal with a terminal status and the reason.
  void end_active(uint8_t status, const std::string& reason) {
    if (!active_) {
      return;
    }
    if (active_->move_base) {
      move_base_msgs::MoveBaseResult result;
      if (status == actionlib_msgs::GoalStatus::SUCCEEDED) {
        active_->move_base->setSucceeded(result, reason);
      } else if (status == actionlib_msgs::GoalStatus::ABORTED) {
        active_->move_base->setAborted(result, reason);
      } else {
        active_->move_base->setCanceled(result, reason);
      }
    }
    if (active_->approach) {
      ApproachResult result;
      result.reason = reason;
      fill_placement(result);
      if (status == actionlib_msgs::GoalStatus::SUCCEEDED) {
        active_->approach->setSucceeded(result, reason);
      } else if (status == actionlib_msgs::GoalStatus::ABORTED) {
        active_->approach->setAborted(result, reason);
      } else {
        active_->approach->setCanceled(result, reason);
      }
    }
    active_.reset();
  }

  // Distance and heading error to the person or o-space centre, as the action reports them.
  void fill_placement(ApproachResult& result) const {
    const std::optional<navigation::RobotObservation> robot = observe_robot();
    if (!navigator_ || !navigator_->goal() || !navigator_->goal()->look_at || !robot) {
      return;
    }
    const Eigen::Vector2d to = *navigator_->goal()->look_at - robot->pose.position;
    result.final_distance = to.norm();
    result.final_heading_error =
        std::abs(core::angle_difference(std::atan2(to.y(), to.x()), robot->pose.theta));
  }

  void finish(navigation::NavigationState state, const std::string& reason) {
    const bool succeeded = state == navigation::NavigationState::kSucceeded;
    end_active(
        succeeded ? actionlib_msgs::GoalStatus::SUCCEEDED : actionlib_msgs::GoalStatus::ABORTED,
        reason);
    if (!succeeded) {
      ROS_WARN("navigation aborted: %s", reason.c_str());
    }
    publish_status(succeeded ? "succeeded" : "aborted: " + reason);
    stop();
  }

  // ---- control loop --------------------------------------------------------------------
  void on_timer(const ros::TimerEvent&) {
    inputs_.publish_when_due(diagnostics_pub_, ros::Time::now());
    tf_.renew_if_stale();
    // People are followed all the time, so that a goal naming someone finds them known already;
    // those perception stopped reporting are let go.
    observe_perception();
    if (waiting_) {
      start_waiting_approach();
    }
    if (!navigator_ || navigator_->state() != navigation::NavigationState::kActive) {
      return;
    }
    const std::optional<navigation::RobotObservation> robot = observe_robot();
    if (!robot) {
      ROS_WARN_THROTTLE(5.0, "social_mpc_node: no transform from map to base_footprint");
      return;
    }
    const ros::Time now = ros::Time::now();
    const navigation::NavigatorStep step =
        navigator_->update(now.toSec(), *robot, tracker_.scene(now.toSec()));
    if (step.state == navigation::NavigationState::kSucceeded ||
        step.state == navigation::NavigationState::kAborted) {
      finish(step.state, step.reason);
      markers_pub_.publish(navigation_markers(*navigator_, false, kMapFrame));
      return;
    }
    command(step.command, now);
    publish_feedback(step, *robot);
    plan_pub_.publish(plan_msg(navigator_->plan(), kMapFrame, now));
    if (markers_pub_.getNumSubscribers() > 0) {
      markers_pub_.publish(navigation_markers(*navigator_, true, kMapFrame));
    }
    char status[128];
    std::snprintf(status, sizeof(status), "%s, %.2f m to go", step.phase.c_str(),
                  step.distance_to_goal_m);
    publish_status(status);
  }

  void command(const navigation::NavigationCommand& command, const ros::Time& now) {
    geometry_msgs::Twist twist;
    twist.linear.x = command.linear_mps;
    twist.angular.z = command.angular_rps;
    cmd_vel_pub_.publish(twist);
    trajectory_msgs::JointTrajectory head;
    head.header.stamp = now;
    head.joint_names = {kHeadPanJoint, kHeadTiltJoint};
    trajectory_msgs::JointTrajectoryPoint point;
    point.positions = {command.pan_rad, 0.0};
    point.time_from_start = ros::Duration(1.0 / config_.navigator.rate_hz);
    head.points.push_back(point);
    head_pub_.publish(head);
  }

  void stop() { cmd_vel_pub_.publish(geometry_msgs::Twist()); }

  void publish_feedback(const navigation::NavigatorStep& step,
                        const navigation::RobotObservation& robot) {
    if (!active_) {
      return;
    }
    if (active_->move_base) {
      move_base_msgs::MoveBaseFeedback feedback;
      feedback.base_position.header.frame_id = kMapFrame;
      feedback.base_position.header.stamp = ros::Time::now();
      feedback.base_position.pose.position.x = robot.pose.position.x();
      feedback.base_position.pose.position.y = robot.pose.position.y();
      feedback.base_position.pose.orientation.z = std::sin(0.5 * robot.pose.theta);
      feedback.base_position.pose.orientation.w = std::cos(0.5 * robot.pose.theta);
      active_->move_base->publishFeedback(feedback);
    }
    if (active_->approach) {
      ApproachFeedback feedback;
      feedback.state = step.phase;
      feedback.distance_to_goal = step.distance_to_goal_m;
      active_->approach->publishFeedback(feedback);
    }
  }

  void publish_status(const std::string& text) {
    if (text == last_status_) {
      return;
    }
    std_msgs::String msg;
    msg.data = text;
    status_pub_.publish(msg);
    last_status_ = text;
  }

  navigation::NavigationConfig config_;
  navigation::SceneTracker tracker_;
  std::unique_ptr<navigation::Navigator> navigator_;
  std::optional<ActiveGoal> active_;
  InputCounters inputs_{"social_mpc_node"};
  // An approach goal whose target is not perceived yet (kTargetWait_s).
  struct WaitingApproach {
    ApproachServer::GoalHandle handle;
    navigation::NavigationTarget target;
    double until_s{0.0};
  };
  std::optional<WaitingApproach> waiting_;
  std::vector<navigation::ReportedGroup> received_groups_;  // since the last observe_perception
  double linear_mps_{0.0}, angular_rps_{0.0}, pan_rad_{0.0}, pan_rps_{0.0};
  std::string last_status_;

  ros::NodeHandle nh_;
  PerceivedPersons persons_;
  RenewingTfBuffer tf_;
  MoveBaseServer move_base_;
  ApproachServer approach_;
  ros::Publisher cmd_vel_pub_, head_pub_, plan_pub_, markers_pub_, status_pub_, diagnostics_pub_;
  ros::Subscriber map_sub_, odom_sub_, joints_sub_, groups_sub_, simple_goal_sub_;
  ros::Timer timer_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  ros::init(argc, argv, "social_mpc_node");
  ros::NodeHandle private_handle("~");
  navigation::NavigationConfig config;
  try {
    config = navigation::NavigationConfig::from_yaml(nodes::read_private_params(private_handle));
  } catch (const core::Error& e) {
    ROS_FATAL("%s", e.what());
    return 2;
  }
  ROS_INFO("social_mpc_node: %s solver, horizon %d x %.2f s, replanning at %.0f Hz",
           navigation::solver_name(config.mpc.solver), config.mpc.horizon_steps, config.mpc.step_s,
           config.navigator.rate_hz);
  nodes::SocialMpcNode node(config);
  ros::spin();
  return 0;
}
