#pragma once

#include <ros/ros.h>

#include <cstdint>
#include <exception>
#include <utility>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::nodes {

/// The exit status of a node stopped by an error: a bad parameter or file (core::ConfigError),
/// a failed request to a core (core::Error) or anything else thrown. scripts/run_launch.py and the
/// rostests tell it from a clean stop (0).
inline constexpr int kNodeErrorExit = 2;

/// A node's main: ros::init as `name` with `init_options` (ros::init_options, e.g.
/// NoSigintHandler for a node that handles its own signals), then `body()`, whose value is the
/// exit status. Whatever `body` throws (core::Error and its ConfigError, or any std::exception)
/// is logged with ROS_FATAL and ends the node with kNodeErrorExit, so that every node stops on a
/// bad parameter alike, naming it, instead of aborting in std::terminate.
template <class Body>
int run_node(int argc, char** argv, const char* name, uint32_t init_options, Body body) {
  ros::init(argc, argv, name, init_options);
  // Held until the error is logged: when the body's last NodeHandle goes, roscpp shuts down, and
  // with it rosconsole, so a ROS_FATAL after that would print nothing.
  const ros::NodeHandle keep_ros_up;
  try {
    return body();
  } catch (const std::exception& e) {  // core::Error is a std::runtime_error
    ROS_FATAL("%s", e.what());
    return kNodeErrorExit;
  }
}

/// run_node with ROS's default init options (its own SIGINT handler).
template <class Body>
int run_node(int argc, char** argv, const char* name, Body body) {
  return run_node(argc, argv, name, 0, std::move(body));
}

}  // namespace ari_social_sim::nodes
