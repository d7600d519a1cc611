#pragma once

#include <vector>

#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/group_tracker.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// Seed 3.5.2 GroupDetectionSensor: GCFF on the perceived bodies (noisy positions and
/// orientations, metres), members named by person id, group ids kept by GroupTracker while
/// membership persists (and for GroupConfig::id_memory_frames after). ARI is not a body, so it
/// is never a member.
class GroupPerception {
 public:
  /// Throws core::ConfigError for invalid GCFF parameters.
  explicit GroupPerception(const GroupConfig& config)
      : detector_(config.gcff), tracker_(config.id_memory_frames) {}

  /// Replaces `groups` with this frame's groups (two or more members each).
  void update(const std::vector<PerceivedBody>& bodies, std::vector<PerceivedGroup>& groups);
  void clear() { tracker_.clear(); }

 private:
  GcffDetector detector_;
  GcffResult result_;
  GroupTracker tracker_;
  std::vector<GcffPerson> persons_;
  Grouping grouping_;
};

}  // namespace ari_social_sim::perception
