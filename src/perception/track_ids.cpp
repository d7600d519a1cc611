#include "ari_social_sim/perception/track_ids.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::perception {

TrackIds::TrackIds(const DetectionErrors& errors, TransientIds& ids, core::Rng rng)
    : errors_(errors), ids_(ids), rng_(rng) {}

void TrackIds::renew(Track& track) {
  switches_ += track.id.empty() ? 0 : 1;
  track.id = ids_.next();
}

const std::string* TrackIds::update(model::ObjectId human, Sighting sighting, double dt_s) {
  Track& track = tracks_[human];
  if (sighting != Sighting::kDetected) {
    track.gap_cause = track.seen_last_frame ? sighting : std::max(track.gap_cause, sighting);
    track.seen_last_frame = false;
    return nullptr;
  }
  if (track.id.empty()) {
    track.id = ids_.next();
  } else if (!track.seen_last_frame) {
    const double reid = track.gap_cause == Sighting::kOccluded    ? errors_.reid_after_occlusion
                        : track.gap_cause == Sighting::kOutOfView ? errors_.reid_after_leaving_fov
                                                                  : 0.0;
    if (reid > 0.0 && rng_.bernoulli(reid)) {
      renew(track);
    }
  } else if (errors_.reid_rate_per_min > 0.0 && dt_s > 0.0) {
    // Probability of at least one switch of a Poisson process during dt.
    const double rate_per_s = errors_.reid_rate_per_min / 60.0;
    if (rng_.bernoulli(1.0 - std::exp(-rate_per_s * dt_s))) {
      renew(track);
    }
  }
  track.seen_last_frame = true;
  track.gap_cause = Sighting::kDetected;
  return &track.id;
}

void TrackIds::retain(const std::set<model::ObjectId>& present) {
  for (auto it = tracks_.begin(); it != tracks_.end();) {
    it = present.count(it->first) > 0 ? std::next(it) : tracks_.erase(it);
  }
}

}  // namespace ari_social_sim::perception
