#pragma once

#include <rosbag/bag.h>

#include <string>

#include "ari_social_sim/core/pending_file.hpp"
#include "ari_social_sim/engine/episode.hpp"

namespace ari_social_sim::tools {

/// One episode's rosbag, written without a ROS master: the topics and message types a live run
/// records with launch/record.launch (docs/scenario.md, "Recording"), stamped with sim time.
/// Deterministic: the same episode gives a byte-identical file.
///
/// Complete or absent: the bag has no name while it is written and gets `path` from finish()
/// (core::PendingFile). Where the file system needs a name, it is `<path>.active`, as
/// `rosbag record` names a bag it is still writing. Destroyed unfinished (an episode interrupted
/// or failed) or killed outright, it leaves nothing but, on such a file system, the .active file
/// of a killed process.
class EpisodeBag {
 public:
  /// Opens the bag for writing. Throws core::Error when it cannot be written.
  EpisodeBag(const std::string& path, const std::string& scenario_name,
             core::PendingFile::Naming naming = core::PendingFile::Naming::unnamed_where_possible);
  /// Drops the bag unless finish() was called.
  ~EpisodeBag();
  EpisodeBag(const EpisodeBag&) = delete;
  EpisodeBag& operator=(const EpisodeBag&) = delete;

  /// Writes what the episode's last step produced; the first call also writes the latched topics
  /// (/map, /tf_static). Throws core::Error naming the file when a write fails (a full disk).
  void record_step(const engine::Episode& episode);
  /// Closes the bag and gives it its name. Throws core::Error naming the path when closing or
  /// naming fails (the bag is then dropped).
  void finish();

  /// The name a bag has while it is written where the file system needs one: `<path>.active`.
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
  core::PendingFile pending_;
  rosbag::Bag bag_;
  std::string scenario_name_;
  bool finished_{false};
  size_t visits_recorded_{0};
  bool started_{false};
};

}  // namespace ari_social_sim::tools
