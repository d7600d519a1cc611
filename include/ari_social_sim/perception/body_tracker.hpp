#pragma once

#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/perception/ari_sensors.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/perception/track_ids.hpp"
#include "ari_social_sim/perception/visibility.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::perception {

/// D6.4 §3.5.2 HumanTrackingSensor: bodies as the torso fisheye tracks them. A human is tracked
/// when inside the fisheye's wedge and range, at least min_visible_fraction of them is visible
/// past walls, furniture and other people, and no miss is drawn (body_errors); tracks keep their
/// id as TrackIds decides; poses carry PoseNoise.
class BodyTracker {
 public:
  /// `config` is the effective configuration (errors already switched off if disabled).
  BodyTracker(const PerceptionConfig& config, TransientIds& ids, core::Rng rng);

  /// Appends this frame's bodies to `bodies`, in the order of snapshot.humans. `obstacles.people`
  /// holds the humans' positions in that order.
  void update(const world::WorldSnapshot& snapshot, const AriSensors& sensors,
              const SightObstacles& obstacles, double dt_s, std::vector<PerceivedBody>& bodies);
  TrackIds& track_ids() { return track_ids_; }
  const TrackIds& track_ids() const { return track_ids_; }

 private:
  const PerceptionConfig& config_;
  TrackIds track_ids_;
  core::Rng rng_;
};

}  // namespace ari_social_sim::perception
