#include "navigation_msgs.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/navigation/social_cost_map.hpp"

namespace ari_social_sim::nodes {
namespace {

using visualization_msgs::Marker;

std_msgs::ColorRGBA rgba(float r, float g, float b, float a) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

geometry_msgs::Point point(const Eigen::Vector2d& p, double z) {
  geometry_msgs::Point msg;
  msg.x = p.x();
  msg.y = p.y();
  msg.z = z;
  return msg;
}

geometry_msgs::Quaternion yaw_quaternion(double theta) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * theta);
  q.w = std::cos(0.5 * theta);
  return q;
}

Marker& add(visualization_msgs::MarkerArray& out, const std::string& frame_id,
            const ros::Time& stamp, const std::string& ns, int id, int type,
            const std_msgs::ColorRGBA& colour) {
  Marker m;
  m.header.frame_id = frame_id;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color = colour;
  out.markers.push_back(std::move(m));
  return out.markers.back();
}

// Heat colour of a social cost density in [0, 1+]: yellow (low) to red (high).
std_msgs::ColorRGBA heat(double value) {
  const float t = static_cast<float>(std::min(value, 1.0));
  return rgba(1.0f, 1.0f - 0.9f * t, 0.1f, 0.15f + 0.45f * t);
}

}  // namespace

world::OccupancyGrid from_msg(const nav_msgs::OccupancyGrid& msg) {
  world::OccupancyGrid grid;
  grid.origin = {msg.info.origin.position.x, msg.info.origin.position.y};
  grid.resolution_m = msg.info.resolution;
  grid.width = static_cast<int>(msg.info.width);
  grid.height = static_cast<int>(msg.info.height);
  grid.cells = msg.data;
  return grid;
}

std::optional<core::Pose2> planar_pose(const geometry_msgs::Pose& pose) {
  const geometry_msgs::Quaternion& q = pose.orientation;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!std::isfinite(norm) || norm < 1e-6 || !std::isfinite(pose.position.x) ||
      !std::isfinite(pose.position.y)) {
    return std::nullopt;
  }
  core::Pose2 planar;
  planar.position = {pose.position.x, pose.position.y};
  planar.theta = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  return planar;
}

nav_msgs::Path plan_msg(const navigation::MpcSolution& plan, const std::string& frame_id,
                        const ros::Time& stamp) {
  nav_msgs::Path path;
  path.header.frame_id = frame_id;
  path.header.stamp = stamp;
  for (const navigation::RobotState& state : plan.states) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position = point(state.position, 0.0);
    pose.pose.orientation = yaw_quaternion(state.theta);
    path.poses.push_back(pose);
  }
  return path;
}

visualization_msgs::MarkerArray navigation_markers(const navigation::Navigator& navigator,
                                                   bool active, const std::string& frame_id,
                                                   const ros::Time& stamp) {
  visualization_msgs::MarkerArray out;
  Marker clear;
  clear.header.frame_id = frame_id;
  clear.action = Marker::DELETEALL;
  out.markers.push_back(clear);
  if (!active || !navigator.goal()) {
    return out;
  }
  const navigation::Goal& goal = *navigator.goal();
  const navigation::MpcProblem& problem = navigator.problem();
  const navigation::PersonalSpaceParams& spaces = navigator.config().mpc.personal_space;

  // Goal pose and what the head camera keeps in view.
  Marker& arrow = add(out, frame_id, stamp, "goal", 0, Marker::ARROW, rgba(0.1f, 0.8f, 0.2f, 1));
  arrow.points = {point(goal.pose.position, 0.05),
                  point(goal.pose.position + 0.5 * goal.pose.heading(), 0.05)};
  arrow.scale.x = 0.06;
  arrow.scale.y = 0.12;
  arrow.scale.z = 0.12;
  if (goal.look_at) {
    Marker& target = add(out, frame_id, stamp, "look_at", 0, Marker::SPHERE,
                         rgba(0.1f, 0.8f, 0.2f, 0.8f));
    target.pose.position = point(*goal.look_at, 1.2);
    target.scale.x = target.scale.y = target.scale.z = 0.15;
  }

  // The predicted footprint outline every few steps of the plan.
  const navigation::FootprintModel& footprint = navigator.footprint();
  const std::vector<Eigen::Vector2d> outline = footprint.outline(0.76);
  const std::vector<navigation::RobotState>& states = navigator.plan().states;
  for (size_t i = 0; i < states.size(); i += 4) {
    core::Pose2 pose;
    pose.position = states[i].position;
    pose.theta = states[i].theta;
    Marker& box = add(out, frame_id, stamp, "plan_footprint", static_cast<int>(i),
                      Marker::LINE_STRIP, rgba(0.2f, 0.4f, 1.0f, 0.7f));
    box.scale.x = 0.02;
    for (size_t k = 0; k <= outline.size(); ++k) {
      box.points.push_back(point(pose.transform(outline[k % outline.size()]), 0.02));
    }
  }

  // Personal-space edges (asymmetric: farther ahead than behind), and o-space circles.
  const double edge_sigmas = spaces.boundary_sigmas;
  int id = 0;
  for (const navigation::ProblemPerson& person : problem.people) {
    const bool reduced = person.space_scale < 1.0;
    Marker& ring = add(out, frame_id, stamp, "personal_space", id++, Marker::LINE_STRIP,
                       reduced ? rgba(0.2f, 0.8f, 0.2f, 0.8f) : rgba(1.0f, 0.5f, 0.0f, 0.9f));
    ring.scale.x = 0.025;
    const navigation::PersonEstimate& p = person.estimate;
    const double front = spaces.sigma_front_m + spaces.front_per_speed_s * p.velocity.norm();
    constexpr int kPieces = 48;
    for (int k = 0; k <= kPieces; ++k) {
      const double a = 2.0 * core::kPi * k / kPieces;
      const double along = edge_sigmas * (std::cos(a) > 0 ? front : spaces.sigma_rear_m) * std::cos(a);
      const double across = edge_sigmas * spaces.sigma_side_m * std::sin(a);
      core::Pose2 frame;
      frame.position = p.position;
      frame.theta = p.heading;
      ring.points.push_back(point(frame.transform({along, across}), 0.03));
    }
  }
  id = 0;
  for (const navigation::ProblemGroup& group : problem.groups) {
    Marker& circle = add(out, frame_id, stamp, "ospace", id++, Marker::LINE_STRIP,
                         group.is_target ? rgba(0.1f, 0.9f, 0.2f, 1.0f) : rgba(0.9f, 0.1f, 0.1f, 1));
    circle.scale.x = 0.04;
    const double radius = navigation::ospace_radius(group.estimate, spaces);
    constexpr int kPieces = 48;
    for (int k = 0; k <= kPieces; ++k) {
      const double a = 2.0 * core::kPi * k / kPieces;
      circle.points.push_back(
          point(group.estimate.centre + radius * Eigen::Vector2d(std::cos(a), std::sin(a)), 0.04));
    }
  }

  // Social cost density around ARI.
  constexpr double kSpacing = 0.2;
  Marker& cost = add(out, frame_id, stamp, "social_cost", 0, Marker::CUBE_LIST, rgba(1, 1, 1, 1));
  cost.scale.x = cost.scale.y = kSpacing;
  cost.scale.z = 0.01;
  for (const navigation::CostSample& sample : navigation::sample_social_cost(
           problem, spaces, problem.start.position, 5.0, kSpacing, 0.05)) {
    cost.points.push_back(point(sample.position, 0.0));
    cost.colors.push_back(heat(sample.value));
  }
  return out;
}

}  // namespace ari_social_sim::nodes
