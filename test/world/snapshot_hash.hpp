#pragma once

// A fingerprint of a world snapshot for the determinism tests: equal hashes mean equal runs.

#include <cstdint>
#include <cstring>

#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::world::test {

/// FNV-1a over every person's pose and gaze (target, direction, since when).
inline uint64_t hash_of(const WorldSnapshot& snapshot) {
  uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 8; ++i) {
      h = (h ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211ULL;
    }
  };
  for (const HumanSnapshot& human : snapshot.humans) {
    mix(human.pose.position.x());
    mix(human.pose.position.y());
    mix(human.pose.theta);
    mix(human.gaze.target);
    mix(human.gaze.direction_rad);
    mix(human.gaze.since_s);
  }
  return h;
}

}  // namespace ari_social_sim::world::test
