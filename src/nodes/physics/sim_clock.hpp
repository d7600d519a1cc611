#pragma once

#include <ros/time.h>

#include <algorithm>

#include "ari_social_sim/physics/ari_physics.hpp"

namespace ari_social_sim::nodes {

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

}  // namespace ari_social_sim::nodes
