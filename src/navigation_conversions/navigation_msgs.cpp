#include "navigation_msgs.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/navigation/social_cost_map.hpp"
#include "node_support/frames.hpp"
#include "world_conversions/marker_builder.hpp"

namespace ari_social_sim::nodes {
namespace {

using visualization_msgs::Marker;

geometry_msgs::Point at(const Eigen::Vector2d& p, double z) {
  return point(p.x(), p.y(), z);
}

// Heat colour of a social cost density in [0, 1+]: yellow (low) to red (high).
std_msgs::ColorRGBA heat(double value) {
  const float t = static_cast<float>(std::min(value, 1.0));
  return rgba(1.0f, 1.0f - 0.9f * t, 0.1f, 0.15f + 0.45f * t);
}

}  // namespace

geometry_msgs::PoseStamped map_goal_msg(const core::Pose2& goal, const ros::Time& stamp) {
  geometry_msgs::PoseStamped msg;
  msg.header.frame_id = kMapFrame;
  msg.header.stamp = stamp;
  msg.pose.position.x = goal.position.x();
  msg.pose.position.y = goal.position.y();
  msg.pose.orientation.z = std::sin(0.5 * goal.theta);
  msg.pose.orientation.w = std::cos(0.5 * goal.theta);
  return msg;
}

navigation::PoseGoalRequest goal_request_of(const geometry_msgs::PoseStamped& goal) {
  navigation::PoseGoalRequest request;
  request.frame_id = goal.header.frame_id;
  request.x = goal.pose.position.x;
  request.y = goal.pose.position.y;
  request.z = goal.pose.position.z;
  request.qx = goal.pose.orientation.x;
  request.qy = goal.pose.orientation.y;
  request.qz = goal.pose.orientation.z;
  request.qw = goal.pose.orientation.w;
  return request;
}

CommandMessages to_msgs(const navigation::BaseCommand& command, const ros::Time& stamp,
                        double control_rate_hz) {
  CommandMessages messages;
  messages.twist.linear.x = command.linear_mps;
  messages.twist.angular.z = command.angular_rps;
  if (command.pan_rad) {
    trajectory_msgs::JointTrajectory head;
    head.header.stamp = stamp;
    head.joint_names = {kHeadPanJoint, kHeadTiltJoint};
    trajectory_msgs::JointTrajectoryPoint point;
    point.positions = {*command.pan_rad, 0.0};
    point.time_from_start = ros::Duration(1.0 / control_rate_hz);
    head.points.push_back(point);
    messages.head = std::move(head);
  }
  return messages;
}

nav_msgs::Path plan_msg(const navigation::MpcSolution& plan, const std::string& frame_id,
                        const ros::Time& stamp) {
  nav_msgs::Path path;
  path.header.frame_id = frame_id;
  path.header.stamp = stamp;
  for (const navigation::RobotState& state : plan.states) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position = at(state.position, 0.0);
    pose.pose.orientation = yaw_quaternion(state.theta);
    path.poses.push_back(pose);
  }
  return path;
}

namespace {

// The predicted footprint outline every few steps of the plan.
void add_plan_footprints(const navigation::Navigator& navigator, MarkerBuilder& markers) {
  const std::vector<Eigen::Vector2d> outline = navigator.footprint().outline(0.76);
  const std::vector<navigation::RobotState>& states = navigator.plan().states;
  for (size_t i = 0; i < states.size(); i += 4) {
    core::Pose2 pose;
    pose.position = states[i].position;
    pose.theta = states[i].theta;
    Marker& box = markers.add("plan_footprint", static_cast<int>(i), Marker::LINE_STRIP,
                              rgba(0.2f, 0.4f, 1.0f, 0.7f));
    box.scale.x = 0.02;
    for (size_t k = 0; k <= outline.size(); ++k) {
      box.points.push_back(at(pose.transform(outline[k % outline.size()]), 0.02));
    }
  }
}

// Personal-space edges (farther ahead than behind; green for the person approached or the
// members joined, whose spaces ARI may enter) and o-space circles (green for the group joined).
void add_social_spaces(const navigation::Navigator& navigator, MarkerBuilder& markers) {
  const navigation::Goal& goal = *navigator.goal();
  const navigation::MpcProblem& problem = navigator.problem();
  const navigation::PersonalSpaceParams& spaces = navigator.config().mpc.personal_space;
  const std_msgs::ColorRGBA green = rgba(0.1f, 0.85f, 0.2f);
  int id = 0;
  for (const navigation::ProblemPerson& person : problem.people) {
    const bool is_target = goal.is_target(person.estimate.id);
    Marker& ring = markers.add("personal_space", id++, Marker::LINE_STRIP,
                               is_target ? green : rgba(1.0f, 0.5f, 0.0f, 0.9f));
    ring.scale.x = 0.025;
    const navigation::PersonEstimate& p = person.estimate;
    const double front = spaces.sigma_front_m + spaces.front_per_speed_s * p.velocity.norm();
    core::Pose2 frame;
    frame.position = p.position;
    frame.theta = p.heading;
    constexpr int kPieces = 48;
    for (int k = 0; k <= kPieces; ++k) {
      const double a = 2.0 * core::kPi * k / kPieces;
      const double along = std::cos(a) * (std::cos(a) > 0 ? front : spaces.sigma_rear_m);
      const double across = std::sin(a) * spaces.sigma_side_m;
      ring.points.push_back(
          at(frame.transform(spaces.boundary_sigmas * Eigen::Vector2d(along, across)), 0.03));
    }
  }
  id = 0;
  for (const navigation::ProblemGroup& group : problem.groups) {
    const Eigen::Vector2d& c = group.estimate.centre;
    markers.circle("ospace", id++, c.x(), c.y(), 0.04,
                   navigation::ospace_radius(group.estimate, spaces), 0.04,
                   group.is_target ? green : rgba(0.9f, 0.1f, 0.1f));
  }
}

// Social cost density around ARI (rviz rejects an empty list, so none when all is clear).
void add_social_cost(const navigation::Navigator& navigator, MarkerBuilder& markers) {
  const navigation::MpcProblem& problem = navigator.problem();
  constexpr double kSpacing = 0.2;
  const std::vector<navigation::CostSample> samples = navigation::sample_social_cost(
      problem, navigator.config().mpc.personal_space, problem.start.position, 5.0, kSpacing, 0.05);
  if (samples.empty()) {
    return;
  }
  Marker& cost = markers.add("social_cost", 0, Marker::CUBE_LIST, rgba(1, 1, 1));
  cost.scale.x = cost.scale.y = kSpacing;
  cost.scale.z = 0.01;
  for (const navigation::CostSample& sample : samples) {
    cost.points.push_back(at(sample.position, 0.01));
    cost.colors.push_back(heat(sample.value));
  }
}

}  // namespace

visualization_msgs::MarkerArray navigation_markers(const navigation::Navigator& navigator,
                                                   bool active, const std::string& frame_id) {
  visualization_msgs::MarkerArray out;
  MarkerBuilder markers(frame_id, out);
  markers.delete_all();
  if (!active || !navigator.goal()) {
    return out;
  }
  const navigation::Goal& goal = *navigator.goal();
  const std_msgs::ColorRGBA green = rgba(0.1f, 0.85f, 0.2f);
  // Goal pose and what the head camera keeps in view.
  markers.arrow("goal", 0, goal.pose.position.x(), goal.pose.position.y(), 0.05, goal.pose.theta,
                0.5, green);
  if (goal.look_at) {
    Marker& target = markers.add("look_at", 0, Marker::SPHERE, green);
    target.pose.position = at(*goal.look_at, 1.2);
    target.scale.x = target.scale.y = target.scale.z = 0.15;
  }
  add_plan_footprints(navigator, markers);
  add_social_spaces(navigator, markers);
  add_social_cost(navigator, markers);
  return out;
}

}  // namespace ari_social_sim::nodes
