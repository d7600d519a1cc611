#include "ari_social_sim/perception/group_tracker.hpp"

#include <algorithm>
#include <iterator>
#include <tuple>

namespace ari_social_sim::perception {
namespace {

// Number of elements two sorted lists share.
size_t overlap(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  size_t count = 0;
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j) {
      ++i;
    } else if (*j < *i) {
      ++j;
    } else {
      ++count;
      ++i;
      ++j;
    }
  }
  return count;
}

struct Candidate {
  size_t shared;
  uint64_t serial;
  size_t previous;
  size_t current;
};

}  // namespace

std::vector<std::string> GroupTracker::update(const Grouping& groups) {
  // The new groups as tracks with sorted members, not yet named.
  std::vector<Track> current(groups.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    current[g].members = groups[g];
    std::sort(current[g].members.begin(), current[g].members.end());
  }

  // Every (previous, new) pair sharing someone, most shared first, then older id, then new order.
  std::vector<Candidate> candidates;
  for (size_t p = 0; p < tracks_.size(); ++p) {
    for (size_t g = 0; g < current.size(); ++g) {
      const size_t shared = overlap(tracks_[p].members, current[g].members);
      if (shared > 0) {
        candidates.push_back({shared, tracks_[p].serial, p, g});
      }
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return std::make_tuple(b.shared, a.serial, a.current) <
           std::make_tuple(a.shared, b.serial, b.current);
  });

  // Greedy assignment, then fresh ids for the rest.
  std::vector<bool> previous_used(tracks_.size(), false);
  for (const Candidate& candidate : candidates) {
    Track& track = current[candidate.current];
    if (!previous_used[candidate.previous] && track.id.empty()) {
      previous_used[candidate.previous] = true;
      track.id = tracks_[candidate.previous].id;
      track.serial = tracks_[candidate.previous].serial;
    }
  }
  std::vector<std::string> ids;
  ids.reserve(current.size());
  for (Track& track : current) {
    if (track.id.empty()) {
      track.serial = next_serial_++;
      track.id = "g" + std::to_string(track.serial);
    }
    ids.push_back(track.id);
  }
  // Unmatched groups are remembered for a few updates, in case they were only missed.
  for (size_t p = 0; p < tracks_.size(); ++p) {
    if (!previous_used[p] && tracks_[p].missed < memory_updates_) {
      current.push_back(std::move(tracks_[p]));
      ++current.back().missed;
    }
  }
  tracks_ = std::move(current);
  return ids;
}

}  // namespace ari_social_sim::perception
