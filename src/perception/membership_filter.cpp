#include "ari_social_sim/perception/membership_filter.hpp"

#include <algorithm>
#include <numeric>

namespace ari_social_sim::perception {
namespace {

// Union-find root of `i`, halving the path on the way.
size_t root(std::vector<size_t>& parent, size_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

}  // namespace

std::vector<std::vector<size_t>> MembershipFilter::update(
    const std::vector<std::string>& ids, const std::vector<std::vector<size_t>>& detected) {
  ++frame_;
  constexpr size_t kAlone = static_cast<size_t>(-1);
  std::vector<size_t> group_of(ids.size(), kAlone);
  for (size_t g = 0; g < detected.size(); ++g) {
    for (size_t member : detected[g]) {
      group_of[member] = g;
    }
  }

  std::vector<size_t> parent(ids.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t i = 0; i < ids.size(); ++i) {
    for (size_t j = i + 1; j < ids.size(); ++j) {
      const bool first = ids[i] < ids[j];
      PairHistory& pair =
          pairs_[first ? std::make_pair(ids[i], ids[j]) : std::make_pair(ids[j], ids[i])];
      const bool together = group_of[i] != kAlone && group_of[i] == group_of[j];
      if (pair.together.size() < static_cast<size_t>(window_frames_)) {
        pair.together.push_back(together);
      } else {
        pair.together[pair.next] = together;
        pair.next = (pair.next + 1) % pair.together.size();
      }
      pair.last_frame = frame_;
      const size_t votes = std::count(pair.together.begin(), pair.together.end(), true);
      if (2 * votes != pair.together.size()) {
        pair.decided_together = 2 * votes > pair.together.size();
      }
      if (pair.decided_together) {
        parent[root(parent, i)] = root(parent, j);
      }
    }
  }
  // A pair not perceived together for a whole window starts afresh when it is again.
  for (auto it = pairs_.begin(); it != pairs_.end();) {
    it = frame_ - it->second.last_frame >= static_cast<uint64_t>(window_frames_) ? pairs_.erase(it)
                                                                                 : std::next(it);
  }

  std::vector<std::vector<size_t>> groups;
  std::vector<size_t> group_at_root(ids.size(), kAlone);
  for (size_t i = 0; i < ids.size(); ++i) {
    const size_t r = root(parent, i);
    if (group_at_root[r] == kAlone) {
      group_at_root[r] = groups.size();
      groups.emplace_back();
    }
    groups[group_at_root[r]].push_back(i);
  }
  groups.erase(std::remove_if(groups.begin(), groups.end(),
                              [](const std::vector<size_t>& g) { return g.size() < 2; }),
               groups.end());
  return groups;
}

}  // namespace ari_social_sim::perception
