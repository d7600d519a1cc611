#include "perceived_persons.hpp"

#include <std_msgs/String.h>
#include <tf2/utils.h>

#include "hri_messages.hpp"
#include "node_support/frames.hpp"
#include "node_support/hri_ids.hpp"
#include "node_support/per_id_handle.hpp"

namespace ari_social_sim::nodes {
namespace {

// The latest transform `target` -> `frame`, or nothing when tf does not have it.
std::optional<geometry_msgs::TransformStamped> latest(const tf2_ros::Buffer& tf,
                                                      const std::string& target,
                                                      const std::string& frame) {
  try {
    return tf.lookupTransform(target, frame, ros::Time(0));
  } catch (const tf2::TransformException&) {
    return std::nullopt;
  }
}

core::Pose2 planar_pose(const geometry_msgs::TransformStamped& t) {
  return {{t.transform.translation.x, t.transform.translation.y},
          tf2::getYaw(t.transform.rotation)};
}

}  // namespace

std::optional<model::BodyPlacement> body_placement(const tf2_ros::Buffer& tf,
                                                   const std::string& frame,
                                                   const std::string& body_id) {
  const std::optional<geometry_msgs::TransformStamped> t = latest(tf, frame, body_frame(body_id));
  if (!t) {
    return std::nullopt;
  }
  return model::BodyPlacement{t->header.stamp.toSec(), planar_pose(*t)};
}

std::optional<model::BodyPlacement> fresh_body_placement(const tf2_ros::Buffer& tf,
                                                         const std::string& frame,
                                                         const std::string& body_id, double now_s) {
  std::optional<model::BodyPlacement> body = body_placement(tf, frame, body_id);
  if (body && body->stamp_s != 0.0 && now_s - body->stamp_s > kStaleBodyFrame_s) {
    body.reset();
  }
  return body;
}

PerceivedPersons::PerceivedPersons(const ros::NodeHandle& nh, double forget_after_s)
    : nh_(nh), forget_after_s_(forget_after_s) {
  tracked_sub_ = nh_.subscribe("/humans/persons/tracked", 1, &PerceivedPersons::on_tracked, this,
                               ros::TransportHints().tcpNoDelay());
}

std::vector<model::TrackedPerson> PerceivedPersons::tracked() const {
  std::vector<model::TrackedPerson> persons;
  persons.reserve(tracked_.size());
  for (const std::string& id : tracked_) {
    const auto followed = followed_.find(id);
    persons.push_back({id, followed == followed_.end() ? "" : followed->second.body_id});
  }
  return persons;
}

std::vector<PerceivedPersons::Placed> PerceivedPersons::place(const tf2_ros::Buffer& tf) const {
  std::vector<Placed> placed;
  for (const model::TrackedPerson& person : tracked()) {
    std::optional<geometry_msgs::TransformStamped> t;
    if (!person.body_id.empty()) {
      t = latest(tf, kMapFrame, body_frame(person.body_id));
    }
    const bool from_body = t.has_value();
    if (!t) {
      t = latest(tf, kMapFrame, person_frame(person.person_id));
    }
    // A frame tf places absurdly (inf, 1e300: a rogue publisher) places nobody.
    if (t && model::pose_problem(planar_pose(*t)).empty()) {
      placed.push_back({person.person_id, t->header.stamp.toSec(), planar_pose(*t), from_body});
    }
  }
  return placed;
}

void PerceivedPersons::on_tracked(const IdsList& msg) {
  // An unstamped list has no time of its own: its arrival time stands in for it.
  const double now_s = (msg.header.stamp.isZero() ? ros::Time::now() : msg.header.stamp).toSec();
  list_time_s_ = now_s;
  tracked_.clear();
  for (const std::string& id : msg.ids) {
    if (is_valid_hri_id(id)) {
      tracked_.push_back(id);
    } else {
      ROS_WARN_THROTTLE(5.0, "/humans/persons/tracked: left out the id '%s', which is no ROS name",
                        id.c_str());
    }
  }
  for (const std::string& id : tracked_) {
    auto [followed, is_new] = followed_.try_emplace(id);
    if (is_new) {
      followed->second.body_id_sub = per_id_handle(nh_).subscribe<std_msgs::String>(
          "/humans/persons/" + id + "/body_id", 1, [this, id](const std_msgs::String::ConstPtr& b) {
            const auto person = followed_.find(id);
            if (person != followed_.end()) {
              person->second.body_id = b->data;
            }
          });
    }
    followed->second.last_tracked_s = now_s;
  }
  for (auto person = followed_.begin(); person != followed_.end();) {
    const double since_s = now_s - person->second.last_tracked_s;
    const bool gone = since_s > forget_after_s_ || since_s < 0.0;
    person = gone ? followed_.erase(person) : std::next(person);
  }
}

}  // namespace ari_social_sim::nodes
