#include "episode_bag.hpp"

#include <rosgraph_msgs/Clock.h>
#include <tf2_msgs/TFMessage.h>

#include "ari_social_sim/core/error.hpp"
#include "dialogue_conversions/dialogue.hpp"
#include "navigation_conversions/navigation_msgs.hpp"
#include "node_support/frames.hpp"
#include "perception_conversions/hri_messages.hpp"
#include "scenario_conversions/scenario_status.hpp"
#include "world_conversions/ari_base.hpp"
#include "world_conversions/world_state.hpp"

namespace ari_social_sim::tools {

template <class Message>
void EpisodeBag::write(const std::string& topic, double stamp_s, const Message& message) {
  try {
    bag_.write(topic, ros::Time(stamp_s), message);
  } catch (const rosbag::BagException& e) {
    throw core::Error(path_ + ": cannot write the bag: " + e.what());
  }
}

std::string EpisodeBag::active_path(const std::string& path) {
  return path + ".active";
}

EpisodeBag::EpisodeBag(const std::string& path, const std::string& scenario_name,
                       core::PendingFile::Naming naming)
    : path_(path), pending_(path, ".active", naming), scenario_name_(scenario_name) {
  try {
    bag_.open(pending_.writable_path(), rosbag::bagmode::Write);
  } catch (const rosbag::BagException& e) {
    throw core::Error(path_ + ": cannot write the bag: " + e.what());
  }
}

EpisodeBag::~EpisodeBag() {
  if (finished_) {
    return;
  }
  try {
    bag_.close();
  } catch (const rosbag::BagException&) {
    // Dropped with pending_ either way.
  }
}

void EpisodeBag::finish() {
  try {
    bag_.close();
  } catch (const rosbag::BagException& e) {
    throw core::Error(path_ + ": cannot close the bag: " + e.what());
  }
  pending_.publish();
  finished_ = true;
}

void EpisodeBag::record_step(const engine::Episode& episode) {
  const double now_s = episode.snapshot().time_s;
  // Latched topics arrive first in a live recording. Bags cannot hold time 0, so everything is
  // written from the first step on (live runs also start one step in: docs/scenario.md).
  if (!started_) {
    started_ = true;
    tf2_msgs::TFMessage statics;
    statics.transforms.push_back(nodes::map_to_odom(0.0));
    write("/tf_static", now_s, statics);
    write("/map", now_s, nodes::to_msg(episode.map(), nodes::kMapFrame, 0.0));
  }
  record_world(episode);
  if (const perception::PerceptionFrame* frame = episode.perception_frame()) {
    record_perception(*frame, episode.perception_config());
  }
  if (episode.groups_detected()) {
    record_groups(episode.perceived_groups(), now_s);
  }
  record_navigation(episode);
  // What dialogue_node publishes.
  const dialogue::SpokenDialogueEvents& said = episode.dialogue_events();
  for (const dialogue::UtteranceEvent& event : said.utterances) {
    const dialogue::Utterance& u = episode.dialogue().live().env().transcript()[event.index];
    write("/sim/dialogue/utterances", now_s, nodes::to_msg(u, event));
  }
  for (const dialogue::OutcomeEvent& outcome : said.outcomes) {
    write("/sim/dialogue/outcome", now_s, nodes::to_msg(outcome));
  }
  const auto& visits = episode.runner().visits();
  if (visits.size() != visits_recorded_ || episode.finished()) {
    write("/scenario/status", now_s, nodes::to_msg(scenario_name_, episode.runner(), now_s));
    visits_recorded_ = visits.size();
  }
}

// What world_node publishes after each step.
void EpisodeBag::record_world(const engine::Episode& episode) {
  const world::WorldSnapshot& snapshot = episode.snapshot();
  const double now_s = snapshot.time_s;
  rosgraph_msgs::Clock clock;
  clock.clock = ros::Time(now_s);
  write("/clock", now_s, clock);
  write("/sim/world_state", now_s, nodes::to_msg(snapshot, nodes::kMapFrame));
  if (snapshot.ari) {
    tf2_msgs::TFMessage tf;
    tf.transforms.push_back(nodes::odom_to_base(snapshot.ari->pose, now_s));
    write("/tf", now_s, tf);
    write("/mobile_base_controller/odom", now_s, nodes::to_odometry(*snapshot.ari, now_s));
  }
}

// What social_mpc_node publishes on each control cycle: the base twist and the head's pan target
// (reached within one cycle), or a stop.
void EpisodeBag::record_navigation(const engine::Episode& episode) {
  const double now_s = episode.snapshot().time_s;
  for (const navigation::BaseCommand& command : episode.navigation_commands()) {
    const nodes::CommandMessages messages =
        nodes::to_msgs(command, ros::Time(now_s), episode.navigation_rate_hz());
    write("/mobile_base_controller/cmd_vel", now_s, messages.twist);
    if (messages.head) {
      write("/head_controller/command", now_s, *messages.head);
    }
  }
}

// What hri_perception_node publishes once per frame (its per-id subtopics are not recorded).
void EpisodeBag::record_perception(const perception::PerceptionFrame& frame,
                                   const perception::PerceptionConfig& config) {
  const double now_s = frame.time_s;
  const nodes::HriFrameMessages messages = nodes::hri_frame_messages(
      frame, perception::person_links(frame), /*with_persons=*/true, config.human_model,
      ros::Time(now_s), nodes::kBaseFrame, nodes::kMapFrame);
  for (const IdsMatch& match : messages.matches) {
    write("/humans/candidate_matches", now_s, match);
  }
  for (const Gaze& gaze : messages.gazes) {
    write("/humans/interactions/gazing", now_s, gaze);
  }
  if (!messages.transforms.empty()) {
    tf2_msgs::TFMessage tf;
    tf.transforms = messages.transforms;
    write("/tf", now_s, tf);
  }
  write("/humans/faces/tracked", now_s, messages.faces_tracked);
  write("/humans/bodies/tracked", now_s, messages.bodies_tracked);
  write("/humans/voices/tracked", now_s, messages.voices_tracked);
  write("/humans/persons/tracked", now_s, messages.persons_tracked);
  write("/humans/persons/known", now_s, messages.persons_known);
}

// What group_detection_node publishes on each /humans/persons/tracked: one Group per group, in
// its reference frame (the map), stamped with the tracked list's stamp.
void EpisodeBag::record_groups(const std::vector<perception::PerceivedGroup>& groups,
                               double now_s) {
  std_msgs::Header header;
  header.stamp = ros::Time(now_s);
  header.frame_id = nodes::kMapFrame;
  for (const perception::PerceivedGroup& group : groups) {
    write("/humans/interactions/groups", now_s, nodes::group_msg(group, header));
  }
}

}  // namespace ari_social_sim::tools
