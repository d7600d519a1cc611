#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::perception {

/// Face, body and voice ids as the ROS4HRI reference detectors make them (ROS4HRI nodes):
/// five lowercase letters that look random (seeded), so a new id always means a new track.
///
/// Guarantee: a new id repeats none of the last kRepeatWindow (26^5 - 1 = 11 881 375) ids issued,
/// and ids never run out. The n-th id is a seeded permutation of the 26^5 five-letter words
/// applied to n mod 26^5 (a Feistel network on 24 bits, cycle-walked into [0, 26^5)), so the
/// generator keeps no set of issued ids: its state is a counter and four round keys, whatever the
/// number of ids issued. An id in use repeats only if its track outlives 11.9 million newer ids
/// (at the 200-person soak's ~29 000 ids per sim-hour, 410 sim-hours; docs/perception.md).
class TransientIds {
 public:
  static constexpr int kLength = 5;
  /// How many ids there are: 26^5.
  static constexpr uint32_t kIdCount = 26u * 26u * 26u * 26u * 26u;
  /// A new id differs from each of the last kRepeatWindow ids issued.
  static constexpr uint32_t kRepeatWindow = kIdCount - 1;

  explicit TransientIds(core::Rng rng);

  /// A fresh id, e.g. "qkzvd".
  std::string next();

  /// Ids issued so far.
  uint64_t issued() const { return issued_; }

 private:
  static constexpr int kRounds = 4;

  /// The seeded permutation of [0, kIdCount).
  uint32_t permute(uint32_t index) const;

  std::array<uint64_t, kRounds> round_keys_{};
  uint64_t issued_{0};
};

}  // namespace ari_social_sim::perception
