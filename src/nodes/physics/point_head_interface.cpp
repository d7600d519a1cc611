#include "point_head_interface.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "node_support/frames.hpp"
#include "odom_frame.hpp"
#include "world_conversions/transform.hpp"

namespace ari_social_sim::nodes {
namespace {

// PAL's head_action: success_angle_threshold (rad) and its default pointing frame.
constexpr double kPointingThresholdRad = 0.01;
constexpr char kDefaultPointingFrame[] = "head_front_camera_color_optical_frame";
// How long a point-head goal waits for tf to know its target frame, and how old the frame's
// newest transform may grow while the goal runs (wall and sim seconds): a goal on a person who
// left fails well within a second, and live frames (10-50 Hz) come far more often.
constexpr double kTfWaitS = 0.5;

}  // namespace

PointHeadInterface::PointHeadInterface(ros::NodeHandle& nh, physics::AriPhysics& physics,
                                       const SimClock& clock, const RenewingTfBuffer& tf)
    : physics_(physics),
      clock_(clock),
      tf_(tf),
      solver_(physics.model()),
      head_(physics.controller("head_controller")),
      server_(nh, "/head_controller/point_head_action", false),
      watch_(kTfWaitS) {
  server_.registerGoalCallback([this](const Server::GoalHandle& goal) { on_goal(goal); });
  server_.registerCancelCallback([this](const Server::GoalHandle& goal) { on_cancel(goal); });
  server_.start();
}

void PointHeadInterface::update_goal() {
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

physics::PointHeadGoal PointHeadInterface::goal_of(const PointHeadGoal& msg) {
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

std::unordered_map<std::string, double> PointHeadInterface::joint_positions() const {
  std::unordered_map<std::string, double> q;
  const std::vector<double> positions = physics_.joint_positions();
  for (size_t j = 0; j < positions.size(); ++j) {
    q[physics_.joint_names()[j]] = positions[j];
  }
  return q;
}

double PointHeadInterface::error_now() const {
  return solver_.pointing_error(target_base_, goal_.pointing_axis, goal_.pointing_frame,
                                joint_positions());
}

double PointHeadInterface::max_velocity_rps(const char* joint) const {
  return physics_.model().joint(joint).max_velocity_rps;
}

bool PointHeadInterface::is_tf_frame(const std::string& frame) const {
  return frame != kMapFrame && frame != kOdomFrame && physics_.model().link_index(frame) < 0;
}

std::optional<geometry_msgs::TransformStamped> PointHeadInterface::latest_tf(
    const std::string& frame, std::string* error) const {
  try {
    return tf_.buffer().lookupTransform(kBaseFrame, frame, ros::Time(0));
  } catch (const tf2::TransformException& e) {
    *error = e.what();
    return std::nullopt;
  }
}

std::optional<Eigen::Vector3d> PointHeadInterface::target_in_base(
    const physics::PointHeadGoal& goal) const {
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

PointHeadInterface::HeadMove PointHeadInterface::plan_move(
    const physics::PointHeadGoal& goal, const Eigen::Vector3d& target_base) const {
  const std::unordered_map<std::string, double> q = joint_positions();
  const physics::HeadAim aim =
      solver_.solve(target_base, goal.pointing_axis, goal.pointing_frame, q);
  if (aim.error_rad > kPointingThresholdRad) {
    throw core::RequestError("target out of the head's reach: the pan and tilt limits leave " +
                             std::to_string(aim.error_rad) + " rad of error");
  }
  HeadMove move;
  move.target_base = target_base;
  move.duration_s = physics::point_head_duration(goal, std::abs(aim.pan_rad - q.at("head_1_joint")),
                                                 std::abs(aim.tilt_rad - q.at("head_2_joint")),
                                                 max_velocity_rps("head_1_joint"),
                                                 max_velocity_rps("head_2_joint"));
  move.trajectory.joint_names = {"head_1_joint", "head_2_joint"};
  move.trajectory.points = {{{aim.pan_rad, aim.tilt_rad}, {0.0, 0.0}, {}, move.duration_s}};
  return move;
}

void PointHeadInterface::start_move(const HeadMove& move) {
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

void PointHeadInterface::abort(const std::string& message) {
  if (moving_) {
    head_.cancel(head_goal_id_, physics_.time_s());
  }
  ROS_WARN("point_head_action: %s", message.c_str());
  active_->setAborted(PointHeadResult(), message);
  active_.reset();
}

bool PointHeadInterface::target_still_in_tf() {
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

void PointHeadInterface::on_goal(Server::GoalHandle goal) {
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

void PointHeadInterface::on_cancel(const Server::GoalHandle& goal) {
  if (active_ && *active_ == goal) {
    if (moving_) {
      head_.cancel(head_goal_id_, physics_.time_s());
    }
    active_->setCanceled();
    active_.reset();
  }
}

}  // namespace ari_social_sim::nodes
