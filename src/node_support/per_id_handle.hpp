#pragma once

#include <ros/node_handle.h>

namespace ari_social_sim::nodes {

/// The NodeHandle to advertise or subscribe the topics of one ROS4HRI id through, to be dropped
/// once they are made. roscpp's NodeHandle keeps a weak pointer to every publisher and subscriber
/// made through it for as long as it lives, and a weak pointer to an object made by
/// boost::make_shared holds the object's whole allocation: made through the node's long-lived
/// handle, the topics of the ids that come and go would each keep a few hundred bytes for good
/// (the live soak, docs/PERFORMANCE.md, saw the nodes grow by megabytes a minute). A copy has a
/// list of its own, freed with it.
inline ros::NodeHandle per_id_handle(const ros::NodeHandle& node) {
  return ros::NodeHandle(node);
}

}  // namespace ari_social_sim::nodes
