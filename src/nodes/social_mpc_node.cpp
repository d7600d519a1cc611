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
#include <tf2/utils.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "ari_social_sim/ApproachAction.h"
#include "ari_social_sim/Group.h"
#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/navigation_session.hpp"
#include "navigation_conversions/measured_ari.hpp"
#include "navigation_conversions/navigation_msgs.hpp"
#include "node_support/frames.hpp"
#include "node_support/input_counters.hpp"
#include "node_support/node_main.hpp"
#include "node_support/renewing_tf_buffer.hpp"
#include "node_support/ros_params.hpp"
#include "node_support/single_publisher.hpp"
#include "perception_conversions/perceived_persons.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::nodes {
namespace {

using MoveBaseServer = actionlib::ActionServer<move_base_msgs::MoveBaseAction>;
using ApproachServer = actionlib::ActionServer<ApproachAction>;
using navigation::GoalState;
using navigation::GoalStatus;

class SocialMpcNode {
 public:
  explicit SocialMpcNode(const navigation::NavigationConfig& config)
      : config_(config),
        session_(config),
        measured_(inputs_),
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
    odom_sub_ = nh_.subscribe("/mobile_base_controller/odom", kCheckedInputQueue,
                              &SocialMpcNode::on_odom, this);
    joints_sub_ =
        nh_.subscribe("/joint_states", kCheckedInputQueue, &SocialMpcNode::on_joints, this);
    groups_sub_ = nh_.subscribe("/humans/interactions/groups", 20, &SocialMpcNode::on_group, this);
    simple_goal_sub_ = nh_.subscribe("/move_base_simple/goal", kCheckedInputQueue,
                                     &SocialMpcNode::on_simple_goal, this);
    move_base_.registerGoalCallback(
        [this](const MoveBaseServer::GoalHandle& h) { on_move_base(h); });
    move_base_.registerCancelCallback(
        [this](const MoveBaseServer::GoalHandle& h) { on_cancel(h.getGoalID()); });
    approach_.registerGoalCallback([this](const ApproachServer::GoalHandle& h) { on_approach(h); });
    approach_.registerCancelCallback(
        [this](const ApproachServer::GoalHandle& h) { on_cancel(h.getGoalID()); });
    inputs_.declare_drop("tf", "map -> base_footprint");
    inputs_.declare_drop("tf", "map -> body_*");
    inputs_.declare_drop("tf", "absurd transform");
    move_base_.start();
    approach_.start();
    // The session looks at perception and runs its cycles at the first call in their periods:
    // one call per look period.
    const double looks_hz =
        navigation::NavigationSession::kLooksPerCycle * session_.control_rate_hz();
    timer_ = nh_.createTimer(ros::Duration(1.0 / looks_hz), &SocialMpcNode::on_timer, this);
    publish_status("idle");
  }

 private:
  // Who asked for a goal, so that its changes reach them: a move_base or approach client, or
  // nobody (/move_base_simple/goal).
  struct GoalClient {
    std::optional<MoveBaseServer::GoalHandle> move_base;
    std::optional<ApproachServer::GoalHandle> approach;
    std::string what;  // for /social_mpc/status: "person human3", "/move_base_simple/goal"
    bool accepted{false};
  };

  // ---- inputs ----------------------------------------------------------------------------
  void on_map(const ros::MessageEvent<const nav_msgs::OccupancyGrid>& event) {
    if (!map_publisher_.accept(event.getPublisherName())) {
      return;
    }
    const nav_msgs::OccupancyGrid& msg = *event.getConstMessage();
    if (const std::optional<InputProblem> problem = input_problem(msg)) {
      inputs_.drop("/map", problem->field, problem->what);
      return;
    }
    apply(session_.set_map(from_msg(msg)));
    ROS_INFO("social_mpc_node: map %ux%u at %.3f m", msg.info.width, msg.info.height,
             msg.info.resolution);
  }

  void on_odom(const nav_msgs::Odometry& msg) { measured_.take(msg); }
  void on_joints(const sensor_msgs::JointState& msg) { measured_.take(msg); }

  void on_group(const Group& msg) {
    session_.receive_group({msg.group_id, msg.header.stamp.toSec(), msg.members});
  }

  // What the session is told now: ARI as measured, the persons perception tracks, each at their
  // body frame in the map from tf.
  // A body frame tf places absurdly (inf, 1e300) is counted and left out: the person's track is
  // not updated until good transforms return.
  navigation::SessionInputs session_inputs() {
    navigation::SessionInputs inputs;
    inputs.now_s = ros::Time::now().toSec();
    inputs.robot = measured_.observe(tf_.buffer());
    inputs.perception.persons = persons_.tracked();
    inputs.perception.locate_body = [this](const std::string& body_id) {
      std::optional<model::BodyPlacement> body = body_placement(tf_.buffer(), kMapFrame, body_id);
      if (body && !inputs_.plausible("map -> body_*", body->pose)) {
        body.reset();
      }
      return body;
    };
    return inputs;
  }

  // ---- goals ---------------------------------------------------------------------------
  void request(const navigation::NavigationTarget& target, GoalClient client) {
    const navigation::SessionOutput out = session_.request(target, session_inputs());
    clients_[session_.newest_goal()] = std::move(client);
    apply(out);
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
    // Without a map yet the goal is accepted and then aborted with that reason (the session).
    if (const navigation::GoalController* controller = session_.controller()) {
      navigation::check_inside_map(in_map, navigation::MapBounds::of(controller->sdf()),
                                   field + "pose.position");
    }
    return in_map;
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
    const navigation::NavigationTarget target = navigation::PoseTarget{pose};
    request(target, {handle, std::nullopt, navigation::describe(target)});
  }

  // The same checks as move_base; with no result channel, a refusal is a warning and the status.
  void on_simple_goal(const geometry_msgs::PoseStamped& goal) {
    core::Pose2 pose;
    try {
      pose = goal_in_map(goal, "");
    } catch (const core::Error& e) {
      ROS_WARN("/move_base_simple/goal ignored: %s", e.what());
      publish_status(std::string("goal ignored: ") + e.what());
      return;
    }
    request(navigation::PoseTarget{pose}, {std::nullopt, std::nullopt, "/move_base_simple/goal"});
  }

  // An approach goal whose request is malformed is rejected with the reason; one naming an id
  // perception does not report yet waits for it (NavigationSession::kTargetWait_s).
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
      ROS_WARN("approach goal rejected: %s", problem.c_str());
      handle.setRejected(with_reason(ApproachResult(), problem), problem);
      return;
    }
    request(*target, {std::nullopt, handle, navigation::describe(*target)});
  }

  void on_cancel(const actionlib_msgs::GoalID& id) {
    for (const auto& [goal, client] : clients_) {
      const bool named = (client.move_base && client.move_base->getGoalID().id == id.id) ||
                         (client.approach && client.approach->getGoalID().id == id.id);
      if (named) {
        apply(session_.cancel(goal));
        return;
      }
    }
  }

  static move_base_msgs::MoveBaseResult with_reason(move_base_msgs::MoveBaseResult result,
                                                    const std::string&) {
    return result;
  }
  static ApproachResult with_reason(ApproachResult result, const std::string& reason) {
    result.reason = reason;
    return result;
  }

  // ---- what the session produced -----------------------------------------------------------
  void apply(const navigation::SessionOutput& out) {
    for (const navigation::GoalChange& change : out.goals) {
      const auto client = clients_.find(change.goal);
      if (client == clients_.end()) {
        continue;
      }
      tell(client->second, change.status);
      if (change.status.state != GoalState::kPending && change.status.state != GoalState::kActive) {
        clients_.erase(client);
      }
    }
    for (const navigation::BaseCommand& command : out.commands) {
      send(command);
    }
  }

  void tell(GoalClient& client, const GoalStatus& status) {
    const bool was_accepted = client.accepted;
    switch (status.state) {
      case GoalState::kPending:
        return;
      case GoalState::kActive:
        publish_status("pursuing " + client.what);
        break;
      case GoalState::kSucceeded:
        publish_status("succeeded");
        break;
      case GoalState::kRejected:
        ROS_WARN("approach goal rejected: %s", status.reason.c_str());
        break;
      case GoalState::kAborted:
        if (was_accepted) {
          ROS_WARN("navigation aborted: %s", status.reason.c_str());
          publish_status("aborted: " + status.reason);
        } else {
          ROS_WARN("goal aborted: %s", status.reason.c_str());
          if (!client.move_base && !client.approach) {
            publish_status("goal ignored: " + status.reason);
          }
        }
        break;
      case GoalState::kCanceled:
        break;
    }
    if (client.move_base) {
      tell_action(*client.move_base, move_base_msgs::MoveBaseResult(), client.accepted, status);
    }
    if (client.approach) {
      ApproachResult result;
      if (was_accepted) {
        fill_placement(result);
      }
      tell_action(*client.approach, result, client.accepted, status);
    }
    client.accepted = client.accepted || status.state == GoalState::kActive;
  }

  // The action's side of a change: a goal is accepted when it is pursued (or, aborted at its
  // start, just before), rejected if it never was.
  template <class Handle, class Result>
  static void tell_action(Handle& handle, Result result, bool accepted, const GoalStatus& status) {
    result = with_reason(result, status.reason);
    switch (status.state) {
      case GoalState::kPending:
        break;
      case GoalState::kActive:
        handle.setAccepted();
        break;
      case GoalState::kSucceeded:
        handle.setSucceeded(result, status.reason);
        break;
      case GoalState::kRejected:
        handle.setRejected(result, status.reason);
        break;
      case GoalState::kAborted:
        if (!accepted) {
          handle.setAccepted();
        }
        handle.setAborted(result, status.reason);
        break;
      case GoalState::kCanceled:
        handle.setCanceled(result, status.reason);
        break;
    }
  }

  // Distance and heading error to the person or o-space centre, as the action reports them.
  void fill_placement(ApproachResult& result) const {
    const navigation::GoalController* controller = session_.controller();
    const std::optional<navigation::RobotObservation> robot = measured_.observe(tf_.buffer());
    if (!controller || !controller->goal() || !controller->goal()->look_at || !robot) {
      return;
    }
    const Eigen::Vector2d to = *controller->goal()->look_at - robot->pose.position;
    result.final_distance = to.norm();
    result.final_heading_error =
        std::abs(core::angle_difference(std::atan2(to.y(), to.x()), robot->pose.theta));
  }

  // ---- control loop --------------------------------------------------------------------
  void on_timer(const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    inputs_.add_drops("tf", "absurd transform", tf_.take_refused().count);
    clock_publishers_.check_when_due();
    inputs_.publish_when_due(diagnostics_pub_, now);
    tf_.renew_if_stale();
    const navigation::SessionInputs inputs = session_inputs();
    if (session_.pursued_goal() != 0 && !inputs.robot) {
      ROS_WARN_THROTTLE(5.0, "social_mpc_node: no transform from map to base_footprint");
    }
    const navigation::GoalId pursued = session_.pursued_goal();
    const navigation::SessionOutput out = session_.control(inputs);
    apply(out);
    if (out.step) {
      publish_cycle(*out.step, *inputs.robot, pursued, now);
    }
  }

  // What a cycle shows besides its commands: the client's feedback, the plan, the markers and
  // the status.
  void publish_cycle(const navigation::NavigatorStep& step,
                     const navigation::RobotObservation& robot, navigation::GoalId goal,
                     const ros::Time& now) {
    // A learned policy has no plan nor MPC markers to show.
    const navigation::Navigator* navigator = session_.navigator();
    if (step.state != navigation::NavigationState::kActive) {
      if (navigator) {
        markers_pub_.publish(navigation_markers(*navigator, false, kMapFrame));
      }
      return;
    }
    if (const auto client = clients_.find(goal); client != clients_.end()) {
      publish_feedback(client->second, step, robot, now);
    }
    if (navigator) {
      plan_pub_.publish(plan_msg(navigator->plan(), kMapFrame, now));
      if (markers_pub_.getNumSubscribers() > 0) {
        markers_pub_.publish(navigation_markers(*navigator, true, kMapFrame));
      }
    }
    char status[128];
    std::snprintf(status, sizeof(status), "%s, %.2f m to go", step.phase.c_str(),
                  step.distance_to_goal_m);
    publish_status(status);
  }

  void send(const navigation::BaseCommand& command) {
    const CommandMessages messages = to_msgs(command, ros::Time::now(), session_.control_rate_hz());
    cmd_vel_pub_.publish(messages.twist);
    if (messages.head) {
      head_pub_.publish(*messages.head);
    }
  }

  static void publish_feedback(GoalClient& client, const navigation::NavigatorStep& step,
                               const navigation::RobotObservation& robot, const ros::Time& now) {
    if (client.move_base) {
      move_base_msgs::MoveBaseFeedback feedback;
      feedback.base_position.header.frame_id = kMapFrame;
      feedback.base_position.header.stamp = now;
      feedback.base_position.pose.position.x = robot.pose.position.x();
      feedback.base_position.pose.position.y = robot.pose.position.y();
      feedback.base_position.pose.orientation.z = std::sin(0.5 * robot.pose.theta);
      feedback.base_position.pose.orientation.w = std::cos(0.5 * robot.pose.theta);
      client.move_base->publishFeedback(feedback);
    }
    if (client.approach) {
      ApproachFeedback feedback;
      feedback.state = step.phase;
      feedback.distance_to_goal = step.distance_to_goal_m;
      client.approach->publishFeedback(feedback);
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
  navigation::NavigationSession session_;
  std::map<navigation::GoalId, GoalClient> clients_;  // of the goals waiting or pursued
  InputCounters inputs_{"social_mpc_node"};
  SinglePublisher map_publisher_{"/map", &inputs_};  // world_node's alone
  PublisherCountWatch clock_publishers_{"/clock"};
  MeasuredAri measured_;
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
  return nodes::run_node(argc, argv, "social_mpc_node", [] {
    ros::NodeHandle private_handle("~");
    const navigation::NavigationConfig config =
        navigation::NavigationConfig::from_yaml(nodes::read_private_params(private_handle));
    nodes::SocialMpcNode node(config);  // throws when the policy file cannot be read
    if (config.navigator.policy_file.empty()) {
      ROS_INFO("social_mpc_node: %s solver, horizon %d x %.2f s, replanning at %.0f Hz",
               navigation::solver_name(config.mpc.solver), config.mpc.horizon_steps,
               config.mpc.step_s, config.navigator.rate_hz);
    } else {
      ROS_INFO("social_mpc_node: the learned policy %s drives ARI instead of SocialMPC",
               config.navigator.policy_file.c_str());
    }
    ros::spin();
    return 0;
  });
}
