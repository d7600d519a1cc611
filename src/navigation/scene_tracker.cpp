#include "ari_social_sim/navigation/scene_tracker.hpp"

#include <cmath>

#include "ari_social_sim/model/tracked_person.hpp"

namespace ari_social_sim::navigation {

void SceneTracker::observe_person(const std::string& id, double time_s,
                                  const Eigen::Vector2d& position, double heading) {
  if (!std::isfinite(time_s) || !model::pose_problem({position, heading}).empty()) {
    return;  // one absurd report would leave the filter at inf or NaN for good
  }
  const double r = config_.position_noise_m * config_.position_noise_m;
  const Eigen::Vector2d facing(std::cos(heading), std::sin(heading));
  auto it = people_.find(id);
  if (it != people_.end() && time_s < it->second.time_s - kTimeWentBack_s) {
    people_.erase(it);  // time went back (a world reset): this is someone new
    it = people_.end();
  }
  if (it == people_.end()) {
    Track track;
    track.id = id;
    track.time_s = time_s;
    track.position = position;
    track.facing = facing;
    // Standing still until shown otherwise, with a walker's speed as the velocity's spread.
    track.covariance << r, 0.0, 0.0, 1.0;
    people_.emplace(id, track);
    return;
  }
  Track& t = it->second;
  const double dt = time_s - t.time_s;
  if (dt <= 0.0) {
    return;  // the same report again (several lookups per cycle)
  }
  // Predict (constant velocity, white-noise acceleration q).
  const double q = config_.acceleration_noise_mps2 * config_.acceleration_noise_mps2;
  Eigen::Matrix2d f;
  f << 1.0, dt, 0.0, 1.0;
  Eigen::Matrix2d process;
  process << 0.25 * dt * dt * dt * dt, 0.5 * dt * dt * dt, 0.5 * dt * dt * dt, dt * dt;
  const Eigen::Vector2d predicted = t.position + t.velocity * dt;
  Eigen::Matrix2d p = f * t.covariance * f.transpose() + q * process;
  // Update with the measured position (both axes share the gain).
  const Eigen::Vector2d gain = p.col(0) / (p(0, 0) + r);
  const Eigen::Vector2d innovation = position - predicted;
  t.position = predicted + gain[0] * innovation;
  t.velocity += gain[1] * innovation;
  p -= gain * p.row(0);
  t.covariance = p;
  const double keep = std::exp(-dt / config_.heading_time_constant_s);
  const Eigen::Vector2d blended = keep * t.facing + (1.0 - keep) * facing;
  if (blended.norm() > 1e-6) {
    t.facing = blended.normalized();
  }
  t.time_s = time_s;
}

void SceneTracker::observe_group(const std::string& id, double time_s,
                                 const std::vector<std::string>& members) {
  if (!std::isfinite(time_s)) {
    return;
  }
  GroupReport& report = groups_[id];
  report.time_s = time_s;
  for (const std::string& member : members) {
    report.members[member] = time_s;
  }
}

PerceivedScene SceneTracker::scene(double time_s) const {
  PerceivedScene scene;
  for (const auto& [id, track] : people_) {
    if (time_s - track.time_s <= config_.person_timeout_s) {
      // Where they are now if they kept walking since perception last saw them.
      PersonEstimate person;
      person.id = id;
      person.position = track.position + track.velocity * (time_s - track.time_s);
      person.velocity = track.velocity;
      person.heading = std::atan2(track.facing.y(), track.facing.x());
      scene.people.push_back(person);
    }
  }
  for (const auto& [id, report] : groups_) {
    if (time_s - report.time_s > config_.group_timeout_s) {
      continue;
    }
    std::vector<PersonEstimate> members;
    for (const auto& [member, seen_s] : report.members) {
      const PersonEstimate* person = scene.find_person(member);
      if (person != nullptr && time_s - seen_s <= config_.group_timeout_s) {
        members.push_back(*person);
      }
    }
    if (members.size() >= 2) {
      scene.groups.push_back(estimate_group(id, members, config_.group_stride_m));
    }
  }
  return scene;
}

void SceneTracker::forget(double time_s) {
  // Reported "later" than now by more than kTimeWentBack_s: before time went back (a world reset),
  // and never timed out otherwise.
  const auto stale = [](double since_s, double timeout_s) {
    return since_s > timeout_s || since_s < -kTimeWentBack_s;
  };
  for (auto it = people_.begin(); it != people_.end();) {
    it = stale(time_s - it->second.time_s, config_.person_timeout_s) ? people_.erase(it)
                                                                     : std::next(it);
  }
  for (auto group = groups_.begin(); group != groups_.end();) {
    std::map<std::string, double>& members = group->second.members;
    for (auto member = members.begin(); member != members.end();) {
      member = stale(time_s - member->second, config_.group_timeout_s) ? members.erase(member)
                                                                       : std::next(member);
    }
    const bool gone = stale(time_s - group->second.time_s, config_.group_timeout_s);
    group = gone ? groups_.erase(group) : std::next(group);
  }
}

void SceneTracker::clear() {
  people_.clear();
  groups_.clear();
}

}  // namespace ari_social_sim::navigation
