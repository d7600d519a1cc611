#pragma once

#include <vector>

#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/group_tracker.hpp"
#include "ari_social_sim/perception/membership_filter.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::perception {

/// Seed 3.5.2 GroupDetectionSensor: GCFF on the perceived bodies (noisy positions and
/// orientations, metres), membership steadied over GroupConfig::membership_window_frames frames
/// (MembershipFilter), members named by person id, group ids kept by GroupTracker while
/// membership persists (and for GroupConfig::id_memory_frames after). ARI is not a body, so it
/// is never a member.
class GroupPerception {
 public:
  /// Throws core::ConfigError for invalid GCFF parameters.
  explicit GroupPerception(const GroupConfig& config)
      : detector_(config.gcff),
        stride_(config.gcff.stride),
        membership_(config.membership_window_frames),
        tracker_(config.id_memory_frames) {}

  /// Replaces `groups` with this frame's groups (two or more members each).
  void update(const std::vector<PerceivedBody>& bodies, std::vector<PerceivedGroup>& groups);
  void clear() {
    membership_.clear();
    tracker_.clear();
  }

 private:
  GcffDetector detector_;
  GcffResult result_;
  double stride_;
  MembershipFilter membership_;
  GroupTracker tracker_;
  std::vector<GcffPerson> persons_;
  std::vector<std::string> ids_;
  std::vector<std::vector<size_t>> detected_;
  Grouping grouping_;
};

}  // namespace ari_social_sim::perception
