#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/perception/group_tracker.hpp"
#include "ari_social_sim/perception/membership_filter.hpp"
#include "ari_social_sim/perception/perception_config.hpp"

namespace ari_social_sim::perception {

/// A conversational group GCFF found among the people given to GroupPerception.
struct PerceivedGroup {
  std::string group_id;
  std::vector<std::string> members;                 ///< Person ids.
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};  ///< O-space centre (the people's frame).
};

/// D6.4 §3.5.2 GroupDetectionSensor, as ROS4HRI's separate group detection: GCFF on whichever
/// people are given each frame (ROS4HRI person ids, positions and body facings in one fixed
/// frame, metres and rad), membership steadied over GroupConfig::membership_window_frames frames
/// (MembershipFilter), group ids kept by GroupTracker while membership persists (and for
/// GroupConfig::id_memory_frames after). group_detection_node and the in-process engines both give
/// it the tracked persons at their bodies (group_candidates_of), placed by tf and by the
/// perception frame.
class GroupPerception {
 public:
  /// Throws core::ConfigError for an invalid config (GroupConfig::validate).
  explicit GroupPerception(const GroupConfig& config)
      : detector_(core::validated(config).gcff),
        stride_(config.gcff.stride),
        membership_(config.membership_window_frames),
        tracker_(config.id_memory_frames) {}

  /// Replaces `groups` with this frame's groups (two or more members each, named by the people's
  /// ids; centres in the people's frame). `people` may be empty; coordinates must be finite and
  /// ids unique.
  void update(const std::vector<GcffPerson>& people, std::vector<PerceivedGroup>& groups);
  /// Forgets membership history and group tracks (a reset of time); new ids stay unique.
  void clear() {
    membership_.clear();
    tracker_.clear();
  }
  /// Person pairs with a membership history (MembershipFilter), and group tracks (GroupTracker).
  size_t pair_count() const { return membership_.pair_count(); }
  size_t group_track_count() const { return tracker_.track_count(); }

 private:
  GcffDetector detector_;
  GcffResult result_;
  double stride_;
  MembershipFilter membership_;
  GroupTracker tracker_;
  std::vector<std::string> ids_;
  std::vector<std::vector<size_t>> detected_;
  Grouping grouping_;
};

}  // namespace ari_social_sim::perception
