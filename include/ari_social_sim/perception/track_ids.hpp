#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/perception/detection_model.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/transient_ids.hpp"

namespace ari_social_sim::perception {

/// Gives each simulated human a track id while a tracker sees them (D6.4 §3.5.2: the simulator's
/// own ids keep tracks consistent through occlusions and exits from the view), with the
/// re-identification errors of DetectionErrors:
///  - re-found after a gap whose worst cause was an occlusion: a new id with
///    reid_after_occlusion; after leaving the view: with reid_after_leaving_fov; a gap of missed
///    detections only keeps the id (trackers bridge them);
///  - while seen frame after frame: a new id at reid_rate_per_min (a Poisson process).
/// With every rate 0 a human keeps one id for the whole run.
class TrackIds {
 public:
  TrackIds(const DetectionErrors& errors, TransientIds& ids, core::Rng rng);

  /// The id of `human` in this frame, or null when the sighting is not kDetected. `dt_s` is the
  /// time since the previous frame. The pointer stays valid until the next call.
  const std::string* update(model::ObjectId human, Sighting sighting, double dt_s);
  /// Forgets the humans not in `present` (removed from the world).
  void retain(const std::set<model::ObjectId>& present);

  /// Ids handed out after a human's first one, over the run.
  uint64_t switches() const { return switches_; }
  /// Humans with a track (those in the world at the last retain()).
  size_t size() const { return tracks_.size(); }

 private:
  struct Track {
    std::string id;
    bool seen_last_frame{false};
    Sighting gap_cause{Sighting::kDetected};
  };

  void renew(Track& track);

  DetectionErrors errors_;
  TransientIds& ids_;
  core::Rng rng_;
  std::map<model::ObjectId, Track> tracks_;
  uint64_t switches_{0};
};

}  // namespace ari_social_sim::perception
