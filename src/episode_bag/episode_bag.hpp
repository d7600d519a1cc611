#pragma once

#include <rosbag/bag.h>

#include <string>

#include "ari_social_sim/engine/episode.hpp"

namespace ari_social_sim::tools {

/// One episode's rosbag, written without a ROS master: the topics and message types a live run
/// records with launch/record.launch (docs/scenario.md, "Recording"), stamped with sim time.
/// Deterministic: the same episode gives a byte-identical file.
///
/// Complete or absent: the bag is written as `<path>.active` (as `rosbag record` names a bag it
/// is still writing) and renamed to `path` by finish(). Destroyed unfinished (an episode
/// interrupted or failed), it deletes the .active file, so that no half episode is ever left
/// under a bag's name.
class EpisodeBag {
 public:
  /// Opens `<path>.active` for writing (replacing any stale one). Throws core::Error when it
  /// cannot be written.
  EpisodeBag(const std::string& path, const std::string& scenario_name);
  /// Deletes the .active file unless finish() was called.
  ~EpisodeBag();
  EpisodeBag(const EpisodeBag&) = delete;
  EpisodeBag& operator=(const EpisodeBag&) = delete;

  /// Writes what the episode's last step produced; the first call also writes the latched topics
  /// (/map, /tf_static). Throws core::Error naming the file when a write fails (a full disk).
  void record_step(const engine::Episode& episode);
  /// Closes the bag and renames it to its final name. Throws core::Error naming the path when
  /// closing or renaming fails (the .active file is then deleted).
  void finish();

  /// The name a bag has while it is written: `<path>.active`.
  static std::string active_path(const std::string& path);

 private:
  template <class Message>
  void write(const std::string& topic, double stamp_s, const Message& message);
  void record_world(const engine::Episode& episode);
  void record_navigation(const engine::Episode& episode);
  void record_perception(const perception::PerceptionFrame& frame,
                         const perception::PerceptionConfig& config);
  void record_groups(const std::vector<perception::PerceivedGroup>& groups, double now_s);

  std::string path_;
  rosbag::Bag bag_;
  std::string scenario_name_;
  bool finished_{false};
  size_t visits_recorded_{0};
  bool started_{false};
};

}  // namespace ari_social_sim::tools
