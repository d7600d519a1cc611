#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/model/person_attributes.hpp"
#include "ari_social_sim/perception/ari_sensors.hpp"
#include "ari_social_sim/world/posture.hpp"

// What ARI perceives in one frame: plain data that hri_perception_node publishes as ROS4HRI
// topics and frames, and that tests and the batch tool read. Poses are in the map frame; heights
// come from PerceptionConfig::human_model. `human` fields name the simulated human behind an
// observation, for tests and diagnostics only (they are never published).

namespace ari_social_sim::perception {

/// The permanent ROS4HRI person id of simulated human N in the "human" id style: "human<N>" (e.g.
/// "human10"), as if ARI recognised everyone from a database of known persons. ARI itself is
/// never a person.
inline std::string person_id_of(model::ObjectId human) {
  return "human" + std::to_string(human);
}

/// A region of an image, normalised to [0, 1] from the top-left corner.
struct ImageRegion {
  double xmin{0.0};
  double ymin{0.0};
  double xmax{0.0};
  double ymax{0.0};
};

/// ROS4HRI engagement levels; values are hri_msgs/EngagementLevel's.
enum class EngagementLevel : uint8_t {
  kUnknown = 0,
  kDisengaged = 1,
  kEngaging = 2,
  kEngaged = 3,
  kDisengaging = 4
};

/// A body tracked by the torso fisheye.
struct PerceivedBody {
  model::ObjectId human{model::kNoObject};
  std::string body_id;
  std::string person_id;   ///< Set by the person manager (PersonRegistry), not the detector.
  core::Pose2 X_map_body;  ///< Mid-hips; theta = body orientation. Noisy.
  double distance_m{0.0};  ///< From the fisheye.
  double visible_fraction{1.0};
  ImageRegion roi;  ///< In the fisheye image.
  /// The world's PostureState::apparent(); no error model changes it.
  world::Posture posture{world::Posture::kStanding};
};

/// A face seen by the head camera, with what the face analysers report about it.
struct PerceivedFace {
  model::ObjectId human{model::kNoObject};
  std::string face_id;
  std::string person_id;   ///< Set by the person manager (PersonRegistry), not the detector.
  core::Pose2 X_map_face;  ///< Sellion; theta = where the face points. Noisy.
  double pitch_rad{0.0};   ///< Positive: the face tips down (a nod).
  /// The world's PostureState::apparent(): a seated person's face is lower.
  world::Posture posture{world::Posture::kStanding};
  double gaze_rad{0.0};                           ///< Gaze direction in the map frame.
  model::ObjectId gaze_target{model::kNoObject};  ///< Whom or what the person looks at.
  double distance_m{0.0};                         ///< From the head camera.
  double age_years{0.0};
  double age_confidence{1.0};
  model::Gender gender{model::Gender::kNonIdentified};
  double gender_confidence{1.0};
  bool mask{false};
  double mask_confidence{1.0};
  model::Emotion emotion{model::Emotion::kNeutral};
  double emotion_confidence{1.0};
  ImageRegion roi;  ///< In the head camera image.
};

/// One LiveSpeech result: a partial hypothesis (`incremental`) or the end of an utterance
/// (`final_text`); the other field is empty.
struct SpeechResult {
  std::string incremental;
  std::string final_text;
  double confidence{1.0};
};

/// A voice the microphone array tracks, and what the recogniser made of it in this frame.
struct PerceivedVoice {
  model::ObjectId human{model::kNoObject};  ///< Whose voice it is taken to be.
  std::string voice_id;
  std::string person_id;  ///< Set by the person manager (PersonRegistry), not the detector.
  Eigen::Vector2d position{Eigen::Vector2d::Zero()};  ///< Sound source.
  bool is_speaking{false};
  std::vector<SpeechResult> speech;  ///< This frame's results, in order; often empty.
  /// The transcript of the utterance going on, or of the last one after it ended.
  std::string transcript;
};

/// Hall's proxemic zone of a tracked person around ARI, as hri_person_manager reports it
/// (`/humans/persons/<id>/proxemic_space`); kUnknown when not tracked or beyond the public zone.
enum class ProxemicSpace : uint8_t { kUnknown, kPersonal, kSocial, kPublic };

/// A permanent person as the person manager reports it: tracked while a face, body or voice of
/// theirs is, known once ever tracked.
struct PersonReport {
  model::ObjectId human{model::kNoObject};
  std::string person_id;
  std::string name;
  bool tracked{false};
  double location_confidence{0.0};  ///< 1 while tracked, to 0 over PersonConfig::location_decay.
  Eigen::Vector2d location{Eigen::Vector2d::Zero()};  ///< Head, last known (map).
  std::string face_id;                                ///< Empty when none is attached.
  std::string body_id;
  std::string voice_id;
  EngagementLevel engagement{EngagementLevel::kUnknown};
  ProxemicSpace proxemic_space{ProxemicSpace::kUnknown};
  double engagement_score{0.0};  ///< This frame's visual social engagement, [0, 1].
};

/// "sender gazes at receiver" between known persons; an empty receiver is ARI.
struct GazeRelation {
  std::string sender;
  std::string receiver;
};

struct PerceptionFrame {
  double time_s{0.0};
  bool has_ari{false};  ///< Without ARI nothing is perceived; persons only decay.
  core::Pose2 X_map_base;
  AriSensors sensors;
  std::vector<PerceivedBody> bodies;  ///< Each list ordered by human id.
  std::vector<PerceivedFace> faces;
  std::vector<PerceivedVoice> voices;
  std::vector<PersonReport> persons;  ///< Every known person.
  std::vector<GazeRelation> gazes;
};

}  // namespace ari_social_sim::perception
