#pragma once

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/buffer.h>

#include <optional>

#include "ari_social_sim/navigation/navigator.hpp"
#include "node_support/input_counters.hpp"

namespace ari_social_sim::nodes {

/// ARI as social_mpc_node measures it for the navigation: its base in the map from tf
/// (map -> base_footprint), its velocities from the latest /mobile_base_controller/odom, its head
/// pan and pan velocity from the latest /joint_states. A field that is not finite is dropped and
/// counted in `inputs`, which must outlive this.
class MeasuredAri {
 public:
  explicit MeasuredAri(InputCounters& inputs) : inputs_(inputs) {}

  void take(const nav_msgs::Odometry& odometry);
  void take(const sensor_msgs::JointState& joints);
  /// Nothing while tf cannot place base_footprint in the map.
  std::optional<navigation::RobotObservation> observe(const tf2_ros::Buffer& tf) const;

 private:
  InputCounters& inputs_;
  double linear_mps_{0.0}, angular_rps_{0.0}, pan_rad_{0.0}, pan_rps_{0.0};
};

}  // namespace ari_social_sim::nodes
