#include "ari_social_sim/navigation/scene_tracker.hpp"

#include <cmath>

namespace ari_social_sim::navigation {

void SceneTrackerConfig::read(const core::YamlMap& map) {
  velocity_time_constant_s =
      map.optional<double>("velocity_time_constant", velocity_time_constant_s, core::positive());
  person_timeout_s = map.optional<double>("person_timeout", person_timeout_s, core::positive());
  group_timeout_s = map.optional<double>("group_timeout", group_timeout_s, core::positive());
  group_stride_m = map.optional<double>("group_stride", group_stride_m, core::between(0.0, 2.0));
  map.finish();
}

void SceneTracker::observe_person(const std::string& id, double time_s,
                                  const Eigen::Vector2d& position, double heading) {
  auto it = people_.find(id);
  if (it == people_.end()) {
    Track track;
    track.estimate.id = id;
    track.estimate.position = position;
    track.estimate.heading = heading;
    track.time_s = time_s;
    people_.emplace(id, track);
    return;
  }
  Track& track = it->second;
  const double dt = time_s - track.time_s;
  if (dt <= 0.0) {
    // Same stamp again (several lookups per cycle): keep the pose, nothing to differentiate.
    track.estimate.position = position;
    track.estimate.heading = heading;
    return;
  }
  const Eigen::Vector2d raw = (position - track.estimate.position) / dt;
  // Exponential smoothing with a time constant, so the estimate does not depend on the rate.
  const double keep = track.has_velocity ? std::exp(-dt / config_.velocity_time_constant_s) : 0.0;
  track.estimate.velocity = keep * track.estimate.velocity + (1.0 - keep) * raw;
  track.has_velocity = true;
  track.estimate.position = position;
  track.estimate.heading = heading;
  track.time_s = time_s;
}

void SceneTracker::observe_group(const std::string& id, double time_s,
                                 const std::vector<std::string>& members) {
  groups_[id] = {members, time_s};
}

PerceivedScene SceneTracker::scene(double time_s) const {
  PerceivedScene scene;
  for (const auto& [id, track] : people_) {
    if (time_s - track.time_s <= config_.person_timeout_s) {
      scene.people.push_back(track.estimate);
    }
  }
  for (const auto& [id, report] : groups_) {
    if (time_s - report.time_s > config_.group_timeout_s) {
      continue;
    }
    std::vector<PersonEstimate> members;
    for (const std::string& member : report.members) {
      if (const PersonEstimate* person = scene.find_person(member)) {
        members.push_back(*person);
      }
    }
    if (members.size() >= 2) {
      scene.groups.push_back(estimate_group(id, members, config_.group_stride_m));
    }
  }
  return scene;
}

void SceneTracker::clear() {
  people_.clear();
  groups_.clear();
}

}  // namespace ari_social_sim::navigation
