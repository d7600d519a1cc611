#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ari_social_sim::perception {

/// Steadies group membership over frames. GCFF on noisy bodies can regroup the same people from
/// one frame to the next (a group of five reported whole, then as three and two, then whole),
/// which no consumer of /humans/interactions/groups can follow. Two people count as together
/// when GCFF grouped them in more than half of the last `window_frames` frames in which both
/// were perceived (exactly half keeps the previous verdict); the groups are the connected sets
/// of people together among those perceived now, two or more each. The first frame a pair is
/// seen decides at once, so a group appears without delay.
class MembershipFilter {
 public:
  /// `window_frames` >= 1; 1 passes GCFF's grouping through unchanged.
  explicit MembershipFilter(int window_frames) : window_frames_(window_frames) {}

  /// `ids`: the people perceived in this frame; `detected`: GCFF's groups as indices into `ids`.
  /// Returns the steadied groups as indices into `ids`, each ascending, ordered by first member.
  std::vector<std::vector<size_t>> update(const std::vector<std::string>& ids,
                                          const std::vector<std::vector<size_t>>& detected);
  /// Forgets every pair.
  void clear() { pairs_.clear(); }
  /// Pairs with a history: those both perceived within the last window_frames frames.
  size_t pair_count() const { return pairs_.size(); }

 private:
  struct PairHistory {
    std::vector<bool> together;  ///< Ring of the last window_frames verdicts.
    size_t next{0};              ///< Where the next verdict goes once the ring is full.
    bool decided_together{false};
    uint64_t last_frame{0};
  };

  int window_frames_;
  uint64_t frame_{0};
  std::map<std::pair<std::string, std::string>, PairHistory> pairs_;
};

}  // namespace ari_social_sim::perception
