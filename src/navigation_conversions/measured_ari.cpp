#include "measured_ari.hpp"

#include <tf2/utils.h>

#include <algorithm>

#include "node_support/frames.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr char kOdomTopic[] = "/mobile_base_controller/odom";

}  // namespace

void MeasuredAri::take(const nav_msgs::Odometry& odometry) {
  const bool linear_ok =
      inputs_.finite(kOdomTopic, "twist.twist.linear.x", odometry.twist.twist.linear.x);
  const bool angular_ok =
      inputs_.finite(kOdomTopic, "twist.twist.angular.z", odometry.twist.twist.angular.z);
  if (linear_ok && angular_ok) {
    linear_mps_ = odometry.twist.twist.linear.x;
    angular_rps_ = odometry.twist.twist.angular.z;
  }
}

void MeasuredAri::take(const sensor_msgs::JointState& joints) {
  const auto it = std::find(joints.name.begin(), joints.name.end(), kHeadPanJoint);
  if (it == joints.name.end()) {
    return;
  }
  const size_t i = static_cast<size_t>(it - joints.name.begin());
  if (i < joints.position.size() &&
      inputs_.finite("/joint_states", "position[head_1_joint]", joints.position[i])) {
    pan_rad_ = joints.position[i];
  }
  if (i < joints.velocity.size() &&
      inputs_.finite("/joint_states", "velocity[head_1_joint]", joints.velocity[i])) {
    pan_rps_ = joints.velocity[i];
  }
}

std::optional<navigation::RobotObservation> MeasuredAri::observe(const tf2_ros::Buffer& tf) const {
  geometry_msgs::TransformStamped t;
  try {
    t = tf.lookupTransform(kMapFrame, kBaseFrame, ros::Time(0));
  } catch (const tf2::TransformException&) {
    return std::nullopt;
  }
  navigation::RobotObservation robot;
  robot.pose.position = {t.transform.translation.x, t.transform.translation.y};
  robot.pose.theta = tf2::getYaw(t.transform.rotation);
  // A rogue map -> odom (x = 1e300) places ARI nowhere, not there, until good transforms return.
  if (!inputs_.plausible("map -> base_footprint", robot.pose)) {
    return std::nullopt;
  }
  robot.linear_mps = linear_mps_;
  robot.angular_rps = angular_rps_;
  robot.pan_rad = pan_rad_;
  robot.pan_rps = pan_rps_;
  return robot;
}

}  // namespace ari_social_sim::nodes
