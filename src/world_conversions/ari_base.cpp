#include "ari_base.hpp"

#include <algorithm>

#include "marker_builder.hpp"

namespace ari_social_sim::nodes {

namespace {

geometry_msgs::TransformStamped planar_transform(const char* parent, const char* child,
                                                 const core::Pose2& child_in_parent,
                                                 double stamp_s) {
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time(stamp_s);
  transform.header.frame_id = parent;
  transform.child_frame_id = child;
  transform.transform.translation.x = child_in_parent.position.x();
  transform.transform.translation.y = child_in_parent.position.y();
  transform.transform.rotation = yaw_quaternion(child_in_parent.theta);
  return transform;
}

}  // namespace

geometry_msgs::TransformStamped map_to_odom(double stamp_s, const core::Pose2& odom_in_map) {
  return planar_transform(kMapFrame, kOdomFrame, odom_in_map, stamp_s);
}

geometry_msgs::TransformStamped odom_to_base(const core::Pose2& base_in_odom, double stamp_s) {
  return planar_transform(kOdomFrame, kBaseFrame, base_in_odom, stamp_s);
}

nav_msgs::Odometry to_odometry(const world::AriSnapshot& ari, double stamp_s) {
  nav_msgs::Odometry odom;
  odom.header.stamp = ros::Time(stamp_s);
  odom.header.frame_id = kOdomFrame;
  odom.child_frame_id = kBaseFrame;
  odom.pose.pose.position.x = ari.pose.position.x();
  odom.pose.pose.position.y = ari.pose.position.y();
  odom.pose.pose.orientation = yaw_quaternion(ari.pose.theta);
  odom.twist.twist.linear.x = ari.linear_mps;
  odom.twist.twist.angular.z = ari.angular_rps;
  return odom;
}

sensor_msgs::JointState joint_states_of(const world::AriSnapshot& ari, double stamp_s) {
  sensor_msgs::JointState joints;
  joints.header.stamp = ros::Time(stamp_s);
  joints.name = {kHeadPanJoint, kHeadTiltJoint};
  joints.position = {ari.head_pan_rad, 0.0};
  joints.velocity = {ari.head_pan_velocity_rps, 0.0};
  for (const char* joint : kJointsAtRest) {
    joints.name.push_back(joint);
    joints.position.push_back(0.0);
    joints.velocity.push_back(0.0);
  }
  return joints;
}

std::optional<double> head_pan_target(const trajectory_msgs::JointTrajectory& command) {
  const auto joint =
      std::find(command.joint_names.begin(), command.joint_names.end(), kHeadPanJoint);
  if (joint == command.joint_names.end() || command.points.empty()) {
    return std::nullopt;
  }
  const auto index = static_cast<size_t>(joint - command.joint_names.begin());
  const trajectory_msgs::JointTrajectoryPoint& last = command.points.back();
  if (index >= last.positions.size()) {
    return std::nullopt;
  }
  return last.positions[index];
}

}  // namespace ari_social_sim::nodes
