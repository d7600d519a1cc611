#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/tracked_person.hpp"

namespace ari_social_sim::nodes {

/// Where tf last placed body_<body_id> in `frame`, or nothing when it cannot place it (yet).
std::optional<model::BodyPlacement> body_placement(const tf2_ros::Buffer& tf,
                                                   const std::string& frame,
                                                   const std::string& body_id);

/// How old (s) the last transform of a body frame may be and still place the person: an older
/// one's publisher has stopped (perception died), and the person would otherwise stand there for
/// ever.
inline constexpr double kStaleBodyFrame_s = 1.0;
/// body_placement, unless the frame's last transform is older than kStaleBodyFrame_s at `now_s`
/// (static frames, stamped 0, never go stale).
std::optional<model::BodyPlacement> fresh_body_placement(const tf2_ros::Buffer& tf,
                                                         const std::string& frame,
                                                         const std::string& body_id, double now_s);

/// Who ROS4HRI perception tracks, for the nodes that act on perceived people (social_mpc_node,
/// group_detection_node, scenario_node): follows /humans/persons/tracked and each tracked person's
/// latched /humans/persons/<id>/body_id. A person who has been out of the tracked list for
/// `forget_after_s` of the lists' time (their stamps; an unstamped list's arrival time) is dropped
/// with its subscription, and so is one last listed "later" than a new list (time went
/// backwards: a world reset, a bag looping), so that memory grows with who is around, not with
/// everyone ever seen; one who comes back is followed again (body_id is latched). Captures `this`
/// in callbacks: not copyable or movable.
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

  /// The last /humans/persons/tracked, in its order, each with their latest body id ("" while
  /// none has arrived or none is matched).
  std::vector<model::TrackedPerson> tracked() const;
  /// The time of the last /humans/persons/tracked; nothing before the first.
  const std::optional<double>& list_time_s() const { return list_time_s_; }
  /// Each tracked person at the latest transform map -> body_<body id>, or, for one without a
  /// body or whose body frame tf does not have, at map -> person_<id>. Persons tf cannot place
  /// are left out, and so are those placed absurdly (model::pose_problem). (Social navigation and
  /// group detection need the body's facing: model::place_at_bodies.)
  std::vector<Placed> place(const tf2_ros::Buffer& tf) const;

 private:
  struct Followed {
    ros::Subscriber body_id_sub;
    std::string body_id;  // empty while the person has no body
    double last_tracked_s{0.0};
  };

  void on_tracked(const IdsList& msg);

  ros::NodeHandle nh_;
  double forget_after_s_;
  ros::Subscriber tracked_sub_;
  std::vector<std::string> tracked_;  // the last /humans/persons/tracked
  std::optional<double> list_time_s_;
  std::map<std::string, Followed> followed_;
};

}  // namespace ari_social_sim::nodes
