#pragma once

#include <string>
#include <unordered_set>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::perception {

/// Face, body and voice ids as the ROS4HRI reference detectors make them (specs/ros4hri.md 1.9):
/// five lowercase letters, here drawn from a seeded generator and never handed out twice in a
/// run, so a new id always means a new track.
class TransientIds {
 public:
  static constexpr int kLength = 5;

  explicit TransientIds(core::Rng rng) : rng_(rng) {}

  /// A fresh id, e.g. "qkzvd".
  std::string next();

 private:
  core::Rng rng_;
  std::unordered_set<std::string> issued_;
};

}  // namespace ari_social_sim::perception
