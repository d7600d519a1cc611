#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/perception/body_tracker.hpp"
#include "ari_social_sim/perception/face_tracker.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/perception/person_registry.hpp"
#include "ari_social_sim/perception/speech_listener.hpp"
#include "ari_social_sim/perception/transient_ids.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::perception {

/// How much per-id state a PerceptionPipeline holds (the soak benchmark prints it): every count
/// follows the people in the world and around ARI, none the run's length.
struct PipelineMemory {
  size_t body_tracks{0};  ///< TrackIds of the fisheye: one per human in the world.
  size_t face_tracks{0};  ///< TrackIds of the head camera: likewise.
  size_t voices{0};       ///< SpeechListener voice tracks: humans in the world ever heard.
  size_t utterances{0};   ///< Utterances being heard.
  size_t persons{0};      ///< Known persons: seen within persons.forget_after.
  size_t person_ids{0};   ///< "random" id style: ids remembered for humans in the world or known.
  size_t engagement_samples{0};  ///< Frames in the persons' engagement windows.
  uint64_t ids_issued{0};        ///< Face, body and voice ids issued so far (a count, not memory).
};

/// ARI's perception of the people around it (D6.4 §3.5.2-3.5.4), one frame per world snapshot:
/// bodies (torso fisheye), faces (head camera), voices and speech (microphones), persons with
/// engagement and gaze relations, with the configured error models. Seeded: the same
/// configuration and snapshots give the same frames. Groups are not part of it: as in ROS4HRI,
/// group detection is a separate stage on whatever persons exist (GroupPerception, fed with
/// group_candidates_of(frame) in process).
///
/// Frames may come at any rate; each advances the trackers by the sim time since the previous
/// one. Sim time going backwards (a world reset) forgets every track and person; a new face, body
/// or voice id repeats none of the last TransientIds::kRepeatWindow handed out. Memory follows
/// the people around, not the run's length: tracks and voices of humans gone from the world are
/// dropped, persons unseen for PersonConfig::forget_after are forgotten (docs/perception.md).
class PerceptionPipeline {
 public:
  /// Throws core::ConfigError if the configuration is invalid.
  explicit PerceptionPipeline(const PerceptionConfig& config);
  PerceptionPipeline(const PerceptionPipeline&) = delete;
  PerceptionPipeline& operator=(const PerceptionPipeline&) = delete;

  /// The static map that blocks sight (walls and furniture). Without one nothing static does.
  void set_sight_map(model::OccupancyGrid grid);
  /// The static map that blocks sound (walls only). Without one the sight map does.
  void set_sound_map(model::OccupancyGrid grid);

  /// From now on no voice or speech is perceived: voices come from elsewhere (speech recognition
  /// on the array's audio, a real ASR), and persons are made from faces and bodies.
  void stop_listening() { listening_ = false; }

  /// Perceives one snapshot. The reference stays valid until the next call.
  const PerceptionFrame& update(const world::WorldSnapshot& snapshot);

  /// The configuration in effect (error models zeroed when errors_enabled is false).
  const PerceptionConfig& config() const { return config_; }

  /// The sizes of its per-id state.
  PipelineMemory memory() const;

 private:
  void forget_everyone();
  std::vector<GazeRelation> gaze_relations(const world::WorldSnapshot& snapshot) const;

  PerceptionConfig config_;
  TransientIds ids_;
  BodyTracker bodies_;
  FaceTracker faces_;
  SpeechListener speech_;
  PersonRegistry persons_;
  std::optional<model::OccupancyGrid> sight_map_;
  std::optional<model::OccupancyGrid> sound_map_;
  std::vector<Eigen::Vector2d> people_;
  std::vector<bool> seated_;  // per entry of people_: not standing and settled
  std::optional<double> last_time_s_;
  bool listening_{true};
  PerceptionFrame frame_;
};

}  // namespace ari_social_sim::perception
