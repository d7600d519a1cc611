#pragma once

#include <rosbag/bag.h>

#include <string>

#include "ari_social_sim/scenario/episode.hpp"

namespace ari_social_sim::tools {

/// One episode's rosbag, written without a ROS master: the topics and message types a live run
/// records with launch/record.launch (docs/scenario.md, "Recording"), stamped with sim time.
/// Deterministic: the same episode gives a byte-identical file.
class EpisodeBag {
 public:
  /// Opens `path` for writing. Throws core::RequestError when the file cannot be written.
  EpisodeBag(const std::string& path, const std::string& scenario_name);
  ~EpisodeBag();
  EpisodeBag(const EpisodeBag&) = delete;
  EpisodeBag& operator=(const EpisodeBag&) = delete;

  /// Writes what the episode's last step produced; the first call also writes the latched topics
  /// (/map, /tf_static).
  void record_step(const scenario::Episode& episode);

 private:
  template <class Message>
  void write(const std::string& topic, double stamp_s, const Message& message);
  void record_world(const scenario::Episode& episode);
  void record_navigation(const scenario::Episode& episode);
  void record_perception(const perception::PerceptionFrame& frame,
                         const perception::PerceptionConfig& config);
  void record_groups(const std::vector<perception::PerceivedGroup>& groups, double now_s);

  rosbag::Bag bag_;
  std::string scenario_name_;
  size_t visits_recorded_{0};
  bool started_{false};
};

}  // namespace ari_social_sim::tools
