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

/// Where a human's face points: toward the gaze direction, turned from the body orientation by
/// at most `head_turn_limit_rad` (the 2D world has gaze but no head).
double head_direction(const world::HumanSnapshot& human, double head_turn_limit_rad);

/// D6.4 §3.5.3 FaceTracker, SoftBioMetrics, FaceMask, Emotion and Gaze sensors: faces as the head
/// camera sees them. A face is seen when the human is inside the head camera's wedge and range,
/// at least its min_visible_fraction is visible, the face points at the camera within
/// max_face_angle, and no miss is drawn (face_errors). A face turned away counts as occluded for
/// re-identification. Each seen face reports age (Gaussian noise, rounded to years), gender
/// (swapped for one of the other two at gender_error_rate), mask (flipped at mask_error_rate),
/// emotion (drawn from the confusion row of the true one), gaze direction and target.
class FaceTracker {
 public:
  FaceTracker(const PerceptionConfig& config, TransientIds& ids, core::Rng rng);

  /// Appends this frame's faces to `faces`, in the order of snapshot.humans.
  void update(const world::WorldSnapshot& snapshot, const AriSensors& sensors,
              const SightObstacles& obstacles, double dt_s, std::vector<PerceivedFace>& faces);
  TrackIds& track_ids() { return track_ids_; }
  const TrackIds& track_ids() const { return track_ids_; }

 private:
  /// Fills the soft biometrics, mask and emotion of `face` from the truth.
  void analyse(const world::HumanSnapshot& human, PerceivedFace& face);

  const PerceptionConfig& config_;
  TrackIds track_ids_;
  core::Rng rng_;
};

}  // namespace ari_social_sim::perception
