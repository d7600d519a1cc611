#include "ari_social_sim/perception/perception_pipeline.hpp"

#include <set>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::perception {
namespace {

// Names the person behind each observation of a frame (every observed human is a known person).
template <class Observation>
void link_to_persons(std::vector<Observation>& observations, const PersonRegistry& persons) {
  for (Observation& observation : observations) {
    observation.person_id = persons.person_id(observation.human);
  }
}

}  // namespace

PerceptionPipeline::PerceptionPipeline(const PerceptionConfig& config)
    : config_(core::validated(config).effective()),
      ids_(core::rng_for(config.seed, core::rng_streams::kPerceptionTransientIds)),
      bodies_(config_, ids_, core::rng_for(config.seed, core::rng_streams::kPerceptionBodies)),
      faces_(config_, ids_, core::rng_for(config.seed, core::rng_streams::kPerceptionFaces)),
      speech_(config_, ids_, core::rng_for(config.seed, core::rng_streams::kPerceptionSpeech)),
      persons_(config_.persons, config_.engagement,
               core::rng_for(config.seed, core::rng_streams::kPerceptionPersonIds)) {}

PipelineMemory PerceptionPipeline::memory() const {
  PipelineMemory memory;
  memory.body_tracks = bodies_.track_ids().size();
  memory.face_tracks = faces_.track_ids().size();
  memory.voices = speech_.voice_count();
  memory.utterances = speech_.utterance_count();
  memory.persons = persons_.known_count();
  memory.person_ids = persons_.remembered_id_count();
  memory.engagement_samples = persons_.engagement_samples();
  memory.ids_issued = ids_.issued();
  return memory;
}

void PerceptionPipeline::set_sight_map(model::OccupancyGrid grid) {
  sight_map_ = std::move(grid);
}

void PerceptionPipeline::set_sound_map(model::OccupancyGrid grid) {
  sound_map_ = std::move(grid);
}

void PerceptionPipeline::forget_everyone() {
  bodies_.track_ids().retain({});
  faces_.track_ids().retain({});
  speech_.clear();
  persons_.clear();
}

std::vector<GazeRelation> PerceptionPipeline::gaze_relations(
    const world::WorldSnapshot& snapshot) const {
  // Receivers must be known persons (REP-155); ARI is the empty receiver.
  std::vector<GazeRelation> gazes;
  const model::ObjectId ari = snapshot.ari ? snapshot.ari->id : model::kNoObject;
  for (const PerceivedFace& face : frame_.faces) {
    if (face.gaze_target == model::kNoObject) {
      continue;
    }
    if (face.gaze_target == ari) {
      gazes.push_back({face.person_id, ""});
    } else if (persons_.is_known(face.gaze_target)) {
      gazes.push_back({face.person_id, persons_.person_id(face.gaze_target)});
    }
  }
  return gazes;
}

const PerceptionFrame& PerceptionPipeline::update(const world::WorldSnapshot& snapshot) {
  if (last_time_s_ && snapshot.time_s < *last_time_s_) {
    forget_everyone();
    last_time_s_.reset();
  }
  const double dt_s = last_time_s_ ? snapshot.time_s - *last_time_s_ : 0.0;
  last_time_s_ = snapshot.time_s;

  frame_.time_s = snapshot.time_s;
  frame_.has_ari = snapshot.ari.has_value();
  frame_.bodies.clear();
  frame_.faces.clear();
  frame_.voices.clear();
  frame_.gazes.clear();

  std::set<model::ObjectId> present;
  people_.clear();
  seated_.clear();
  for (const world::HumanSnapshot& human : snapshot.humans) {
    present.insert(human.id);
    people_.push_back(human.pose.position);
    seated_.push_back(!human.posture.is_standing());
  }
  bodies_.track_ids().retain(present);
  faces_.track_ids().retain(present);

  if (snapshot.ari) {
    frame_.X_map_base = snapshot.ari->pose;
    frame_.sensors = AriSensors::of(*snapshot.ari, config_);
    const SightObstacles obstacles{sight_map_ ? &*sight_map_ : nullptr,
                                   config_.occlusion.occupied_threshold, &people_,
                                   config_.occlusion.person_radius_m, &seated_};
    bodies_.update(snapshot, frame_.sensors, obstacles, dt_s, frame_.bodies);
    faces_.update(snapshot, frame_.sensors, obstacles, dt_s, frame_.faces);
    const model::OccupancyGrid* sound_map =
        sound_map_ ? &*sound_map_ : (sight_map_ ? &*sight_map_ : nullptr);
    if (listening_) {
      speech_.update(snapshot, frame_.sensors, sound_map, config_.occlusion.occupied_threshold,
                     frame_.voices);
    }
  }
  persons_.update(snapshot, snapshot.ari ? &frame_.sensors : nullptr, frame_.bodies, frame_.faces,
                  frame_.voices, frame_.persons);
  // The detectors know nothing of persons: the person manager links them.
  link_to_persons(frame_.bodies, persons_);
  link_to_persons(frame_.faces, persons_);
  link_to_persons(frame_.voices, persons_);
  frame_.gazes = gaze_relations(snapshot);
  return frame_;
}

}  // namespace ari_social_sim::perception
