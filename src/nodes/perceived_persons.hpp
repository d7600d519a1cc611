#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/core/pose2.hpp"

namespace ari_social_sim::nodes {

/// Who ROS4HRI perception tracks and where, for the nodes that act on perceived people
/// (social_mpc_node, scenario_node): follows /humans/persons/tracked and each tracked person's
/// latched /humans/persons/<id>/body_id, and places persons with tf. A person who has been out of
/// the tracked list for `forget_after_s` of ROS time is dropped with its subscription, so that
/// memory grows with who is around, not with everyone ever seen; one who comes back is followed
/// again (body_id is latched). Captures `this` in callbacks: not copyable or movable.
class PerceivedPersons {
 public:
  /// A tracked person placed in the map frame.
  struct Placed {
    std::string person_id;
    double stamp_s{0.0};      ///< Of the transform.
    core::Pose2 X_map_frame;  ///< body_<body id> (theta: the body's facing), or person_<id>.
    bool from_body{true};     ///< False: person_<id>, whose orientation means nothing (REP-155).
  };

  explicit PerceivedPersons(const ros::NodeHandle& nh, double forget_after_s = 10.0);
  PerceivedPersons(const PerceivedPersons&) = delete;
  PerceivedPersons& operator=(const PerceivedPersons&) = delete;

  /// Each tracked person at the latest transform map -> body_<body id>; with `or_person_frame`,
  /// one without a body, or whose body frame tf does not have, at map -> person_<id>. Persons tf
  /// cannot place are left out.
  std::vector<Placed> place(const tf2_ros::Buffer& tf, bool or_person_frame) const;

 private:
  struct Followed {
    ros::Subscriber body_id_sub;
    std::string body_id;  // empty while the person has no body
    ros::Time last_tracked;
  };

  void on_tracked(const IdsList& msg);

  ros::NodeHandle nh_;
  double forget_after_s_;
  ros::Subscriber tracked_sub_;
  std::vector<std::string> tracked_;  // the last /humans/persons/tracked
  std::map<std::string, Followed> followed_;
};

}  // namespace ari_social_sim::nodes
