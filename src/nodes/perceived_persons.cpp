#include "perceived_persons.hpp"

#include <std_msgs/String.h>
#include <tf2/utils.h>

#include <optional>

#include "conversions/hri_messages.hpp"
#include "frames.hpp"
#include "hri_ids.hpp"
#include "per_id_handle.hpp"

namespace ari_social_sim::nodes {
namespace {

// The latest transform map -> `frame`, or nothing when tf does not have it.
std::optional<geometry_msgs::TransformStamped> latest_in_map(const tf2_ros::Buffer& tf,
                                                             const std::string& frame) {
  try {
    return tf.lookupTransform(kMapFrame, frame, ros::Time(0));
  } catch (const tf2::TransformException&) {
    return std::nullopt;
  }
}

}  // namespace

PerceivedPersons::PerceivedPersons(const ros::NodeHandle& nh, double forget_after_s)
    : nh_(nh), forget_after_s_(forget_after_s) {
  tracked_sub_ = nh_.subscribe("/humans/persons/tracked", 1, &PerceivedPersons::on_tracked, this);
}

std::vector<PerceivedPersons::Placed> PerceivedPersons::place(const tf2_ros::Buffer& tf,
                                                              bool or_person_frame) const {
  std::vector<Placed> placed;
  for (const std::string& id : tracked_) {
    const auto followed = followed_.find(id);
    const bool has_body = followed != followed_.end() && !followed->second.body_id.empty();
    bool from_body = true;
    std::optional<geometry_msgs::TransformStamped> t;
    if (has_body) {
      t = latest_in_map(tf, body_frame(followed->second.body_id));
    }
    if (!t && or_person_frame) {
      t = latest_in_map(tf, person_frame(id));
      from_body = false;
    }
    if (!t) {
      continue;
    }
    placed.push_back({id,
                      t->header.stamp.toSec(),
                      {{t->transform.translation.x, t->transform.translation.y},
                       tf2::getYaw(t->transform.rotation)},
                      from_body});
  }
  return placed;
}

void PerceivedPersons::on_tracked(const IdsList& msg) {
  const ros::Time now = ros::Time::now();
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
    Followed& followed = followed_[id];
    followed.last_tracked = now;
    if (!followed.body_id_sub) {
      followed.body_id_sub = per_id_handle(nh_).subscribe<std_msgs::String>(
          "/humans/persons/" + id + "/body_id", 1, [this, id](const std_msgs::String::ConstPtr& b) {
            const auto person = followed_.find(id);
            if (person != followed_.end()) {
              person->second.body_id = b->data;
            }
          });
    }
  }
  for (auto person = followed_.begin(); person != followed_.end();) {
    const bool gone = (now - person->second.last_tracked).toSec() > forget_after_s_;
    person = gone ? followed_.erase(person) : std::next(person);
  }
}

}  // namespace ari_social_sim::nodes
