// group_detection_node: ROS4HRI group detection as the separate stage it is in the real stack:
// GCFF (the perception core's GroupPerception) on whichever persons /humans/persons/tracked
// lists, each placed at their body frame from tf, whoever publishes them (hri_perception_node or
// real detectors). Reads parameters, builds the core, wires topics and tf, converts at the edges.

#include <ros/package.h>
#include <ros/ros.h>
#include <visualization_msgs/MarkerArray.h>

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/Group.h"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/perception/group_detection_run_config.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "node_support/node_main.hpp"
#include "node_support/renewing_tf_buffer.hpp"
#include "node_support/ros_params.hpp"
#include "perception_conversions/group_markers.hpp"
#include "perception_conversions/hri_messages.hpp"
#include "perception_conversions/perceived_persons.hpp"

namespace ari_social_sim::nodes {
namespace {

// A person's body_id subscription outlives their last appearance in /humans/persons/tracked by
// this much (s of the lists' time), so that a person missed for a moment keeps it (and their
// latched body id) while the number of subscriptions stays bounded by the people seen recently.
constexpr double kForgetPersonAfter_s = 5.0;

class GroupDetectionNode {
 public:
  GroupDetectionNode(const perception::GroupDetectionRunConfig& run,
                     const perception::GroupConfig& config)
      : run_(run), groups_(config), persons_(nh_, kForgetPersonAfter_s) {
    groups_pub_ = nh_.advertise<Group>("/humans/interactions/groups", 20);
    markers_ = private_nh_.advertise<visualization_msgs::MarkerArray>("markers", 1);
    timer_ = nh_.createTimer(ros::Duration(1.0 / run_.rate_hz), &GroupDetectionNode::detect, this);
  }

 private:
  // Detection runs on the timer with the latest tracked list: a person manager may send the list
  // only when it changes (hri_person_manager does).
  void detect(const ros::TimerEvent&) {
    tf_.renew_if_stale();
    const std::optional<double> list_s = persons_.list_time_s();
    if (!list_s) {
      return;  // nobody has said who is tracked yet
    }
    if (last_list_s_ && *list_s < *last_list_s_) {
      // Time went backwards (a world reset, a bag looping): who stood with whom before is void.
      groups_.clear();
    }
    last_list_s_ = list_s;
    const ros::Time now = ros::Time::now();
    // A timer that fell behind (a busy machine) fires twice at the same sim time: the world has
    // not moved in between, and a second report with the same stamp would only repeat the first.
    // (Time going back, after a world reset, is a new detection.)
    if (now == last_detection_) {
      return;
    }
    last_detection_ = now;
    groups_.update(candidates(now), detected_);
    publish(now);
  }

  // Each tracked person at their body frame in the reference frame, in the list's order
  // (perception::group_candidates_of). Also left out: a person whose body frame tf cannot place
  // yet (its first transform still on the way), and one whose body frame has gone stale
  // (fresh_body_placement).
  std::vector<perception::GcffPerson> candidates(const ros::Time& now) const {
    const auto locate_body = [&](const std::string& body_id) {
      return fresh_body_placement(tf_.buffer(), run_.reference_frame, body_id, now.toSec());
    };
    return perception::group_candidates_of({persons_.tracked(), locate_body});
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

  ros::NodeHandle nh_;
  ros::NodeHandle private_nh_{"~"};
  perception::GroupDetectionRunConfig run_;
  perception::GroupPerception groups_;
  std::vector<perception::PerceivedGroup> detected_;
  std::optional<double> last_list_s_;  // of the list the last detection ran on
  ros::Time last_detection_;
  PerceivedPersons persons_;
  RenewingTfBuffer tf_;
  ros::Publisher groups_pub_, markers_;
  ros::Timer timer_;
};

}  // namespace
}  // namespace ari_social_sim::nodes

int main(int argc, char** argv) {
  using namespace ari_social_sim;
  return nodes::run_node(argc, argv, "group_detection", [] {
    ros::NodeHandle private_handle("~");
    perception::GroupDetectionRunConfig run =
        perception::GroupDetectionRunConfig::from_yaml(nodes::read_private_params(private_handle));
    if (run.config.empty()) {
      run.config = ros::package::getPath("ari_social_sim") + "/config/perception.yaml";
    }
    // The whole file is read and checked, as hri_perception_node reads it; only `groups:` is used.
    const perception::GroupConfig config =
        perception::PerceptionConfig::load_file(run.config).groups;
    ROS_INFO(
        "group_detection_node: GCFF stride %.2f m, mdl %.2f m^2 (%s), people in %s, at %.0f Hz",
        config.gcff.stride, config.gcff.mdl, run.config.c_str(), run.reference_frame.c_str(),
        run.rate_hz);
    nodes::GroupDetectionNode node(run, config);
    ros::spin();
    return 0;
  });
}
