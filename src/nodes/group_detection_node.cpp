// group_detection_node: ROS4HRI group detection as the separate stage it is in the real stack:
// GCFF (the perception core's GroupPerception) on whichever persons /humans/persons/tracked
// lists, each placed at their body frame from tf, whoever publishes them (hri_perception_node or
// real detectors). Reads parameters, builds the core, wires topics and tf, converts at the edges.

#include <ros/package.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>
#include <visualization_msgs/MarkerArray.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/Group.h"
#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/group_detection_run_config.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "conversions/group_markers.hpp"
#include "conversions/hri_messages.hpp"
#include "hri_ids.hpp"
#include "per_id_handle.hpp"
#include "renewing_tf_buffer.hpp"
#include "ros_params.hpp"

namespace ari_social_sim::nodes {
namespace {

// A person's body_id subscription outlives their last appearance in /humans/persons/tracked by
// this much (s of the lists' time), so that a person missed for a moment keeps it (and their
// latched body id) while the number of subscriptions stays bounded by the people seen recently.
constexpr double kForgetPersonAfter_s = 5.0;
// A body frame whose last transform is older than this (s) no longer places anyone: its
// publisher has stopped (perception died) and the person would otherwise stand there for ever.
constexpr double kStaleBodyFrame_s = 1.0;

class GroupDetectionNode {
 public:
  GroupDetectionNode(const perception::GroupDetectionRunConfig& run,
                     const perception::GroupConfig& config)
      : run_(run), groups_(config) {
    groups_pub_ = nh_.advertise<Group>("/humans/interactions/groups", 20);
    markers_ = private_nh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
    tracked_sub_ = nh_.subscribe("/humans/persons/tracked", 1, &GroupDetectionNode::on_tracked,
                                 this, ros::TransportHints().tcpNoDelay());
    timer_ = nh_.createTimer(ros::Duration(1.0 / run_.rate_hz), &GroupDetectionNode::detect, this);
  }

 private:
  struct Person {
    ros::Subscriber body_id_sub;
    std::string body_id;  // Empty until the latched body_id arrives, or while no body is matched.
    double last_tracked_s{0.0};
  };

  // The persons tracked now. A person manager may send the list only when it changes
  // (hri_person_manager does), so detection runs on the timer with the latest list.
  void on_tracked(const IdsList::ConstPtr& msg) {
    // An unstamped list has no time of its own: its arrival time stands in for it.
    const double time_s =
        (msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp).toSec();
    if (last_list_s_ && time_s < *last_list_s_) {
      // Time went backwards (a world reset, a bag looping): who stood with whom before is void.
      groups_.clear();
    }
    last_list_s_ = time_s;
    tracked_.clear();
    for (const std::string& id : msg->ids) {
      if (is_valid_hri_id(id)) {
        tracked_.push_back(id);
      } else {
        ROS_WARN_THROTTLE(5.0, "/humans/persons/tracked: left out the id '%s', no ROS name",
                          id.c_str());
      }
    }
    follow(tracked_, time_s);
  }

  void detect(const ros::TimerEvent&) {
    tf_.renew_if_stale();
    if (!last_list_s_) {
      return;  // nobody has said who is tracked yet
    }
    const ros::Time now = ros::Time::now();
    // A timer that fell behind (a busy machine) fires twice at the same sim time: the world has
    // not moved in between, and a second report with the same stamp would only repeat the first.
    // (Time going back, after a world reset, is a new detection.)
    if (now == last_detection_) {
      return;
    }
    last_detection_ = now;
    groups_.update(candidates(tracked_, now), detected_);
    publish(now);
  }

  // Subscribes to the latched body id of each person that appears; drops those gone for
  // kForgetPersonAfter_s (or seen "later" than now, after time went backwards).
  void follow(const std::vector<std::string>& tracked, double now_s) {
    for (const std::string& id : tracked) {
      auto [it, is_new] = persons_.try_emplace(id);
      if (is_new) {
        it->second.body_id_sub = per_id_handle(nh_).subscribe<std_msgs::String>(
            "/humans/persons/" + id + "/body_id", 1,
            [this, id](const std_msgs::String::ConstPtr& body) {
              const auto person = persons_.find(id);
              if (person != persons_.end()) {
                person->second.body_id = body->data;
              }
            });
      }
      it->second.last_tracked_s = now_s;
    }
    for (auto it = persons_.begin(); it != persons_.end();) {
      const double since_s = now_s - it->second.last_tracked_s;
      it = since_s > kForgetPersonAfter_s || since_s < 0.0 ? persons_.erase(it) : std::next(it);
    }
  }

  // Each tracked person at their body frame in the reference frame, in the list's order: the
  // translation, and the yaw of the frame's x axis, which REP-155 points where the body faces.
  // Left out: a person without a body (only a face or a voice is tracked, or the body is not
  // matched yet), since GCFF needs the body's facing and a face or voice frame gives none; one
  // whose body frame tf cannot place yet (its first transform still on the way); and one whose
  // body frame has not moved on for kStaleBodyFrame_s (static frames, stamped 0, never go stale).
  std::vector<perception::GcffPerson> candidates(const std::vector<std::string>& tracked,
                                                 const ros::Time& now) const {
    std::vector<perception::GcffPerson> people;
    for (const std::string& id : tracked) {
      const auto person = persons_.find(id);
      if (person == persons_.end() || person->second.body_id.empty()) {
        continue;
      }
      geometry_msgs::TransformStamped t;
      try {
        t = tf_.buffer().lookupTransform(run_.reference_frame, body_frame(person->second.body_id),
                                         ros::Time(0));
      } catch (const tf2::TransformException&) {
        continue;
      }
      if (!t.header.stamp.isZero() && (now - t.header.stamp).toSec() > kStaleBodyFrame_s) {
        continue;
      }
      people.push_back({id, t.transform.translation.x, t.transform.translation.y,
                        tf2::getYaw(t.transform.rotation)});
    }
    return people;
  }

  void publish(const ros::Time& stamp) {
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = run_.reference_frame;
    for (const perception::PerceivedGroup& group : detected_) {
      groups_pub_.publish(group_msg(group, header));
    }
    if (markers_.getNumSubscribers() > 0) {
      markers_.publish(group_markers(detected_, run_.reference_frame));
    }
  }

  perception::GroupDetectionRunConfig run_;
  perception::GroupPerception groups_;
  std::vector<perception::PerceivedGroup> detected_;
  std::vector<std::string> tracked_;
  std::optional<double> last_list_s_;
  ros::Time last_detection_;
  std::map<std::string, Person> persons_;

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_{"~"};
  RenewingTfBuffer tf_;
  ros::Publisher groups_pub_, markers_;
  ros::Subscriber tracked_sub_;
  ros::Timer timer_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  ros::init(argc, argv, "group_detection");
  ros::NodeHandle private_handle("~");
  perception::GroupDetectionRunConfig run;
  perception::GroupConfig config;
  try {
    run =
        perception::GroupDetectionRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (run.config.empty()) {
      run.config = ros::package::getPath("ari_social_sim") + "/config/perception.yaml";
    }
    // The whole file is read and checked, as hri_perception_node reads it; only `groups:` is used.
    config = perception::PerceptionConfig::load_file(run.config).groups;
  } catch (const core::Error& e) {
    ROS_FATAL("%s", e.what());
    return 2;
  }
  ROS_INFO("group_detection_node: GCFF stride %.2f m, mdl %.2f m^2 (%s), people in %s, at %.0f Hz",
           config.gcff.stride, config.gcff.mdl, run.config.c_str(), run.reference_frame.c_str(),
           run.rate_hz);
  nodes::GroupDetectionNode node(run, config);
  ros::spin();
  return 0;
}
