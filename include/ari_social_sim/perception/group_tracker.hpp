#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/perception/grouping.hpp"

namespace ari_social_sim::perception {

/// Gives the groups detected frame after frame ids that stay the same while their membership
/// persists, for the ROS4HRI `hri_msgs/Group.group_id` (a string).
///
/// Each update matches the new groups to the previous frame's groups greedily by the number of
/// members they share: the pair sharing most members first (ties: the older id, then the earlier
/// new group), each group used at most once, pairs sharing nobody never matched. A matched group
/// keeps the previous id, so a group that gains or loses members keeps its id, a group that splits
/// leaves it to the part with most of its members, and groups that merge take the id of the one
/// contributing most. Unmatched groups get a fresh id "g<n>" from a counter (n = 1, 2, ...; a
/// valid identifier, never reused). A group that no new group matches is remembered for
/// `memory_updates` more updates (0: only the previous frame counts), so that a group whose
/// members were missed for a few frames comes back with its id.
class GroupTracker {
 public:
  explicit GroupTracker(int memory_updates = 0) : memory_updates_(memory_updates) {}

  /// Ids for `groups` (each a list of person ids), in the same order.
  std::vector<std::string> update(const Grouping& groups);

  /// Forgets the previous frame; the counter goes on, so ids stay unique.
  void clear() { tracks_.clear(); }
  /// Groups held: the last update's and those remembered for memory_updates.
  size_t track_count() const { return tracks_.size(); }

 private:
  struct Track {
    std::string id;
    uint64_t serial{0};                ///< Creation order: lower is older.
    std::vector<std::string> members;  ///< Sorted.
    int missed{0};                     ///< Updates since it was last matched.
  };

  int memory_updates_;
  std::vector<Track> tracks_;
  uint64_t next_serial_{1};
};

}  // namespace ari_social_sim::perception
