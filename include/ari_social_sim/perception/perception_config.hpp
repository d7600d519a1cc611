#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/model/person_attributes.hpp"
#include "ari_social_sim/perception/gcff.hpp"

// Parameters of ARI's simulated perception (docs/perception.md). Defaults are ARI's sensors
// (ari_robot's URDF, D6.4 §3.5) and moderate error levels; config/perception.yaml spells them out.
// Every struct lists its fields once in `visit`, which drives reading, writing and bound checks:
// v.field(name, member, bounds) for values, v.section(name, member) for nested structs. Angles
// are in degrees where the name says `_deg`, lengths in metres, rates are probabilities per event
// unless the name gives a unit.

namespace ari_social_sim::perception {

/// The torso front fisheye that tracks bodies (D6.4 §3.5.2; ELP IMX179, 180 degrees).
struct BodyCameraConfig {
  double x_m{-0.142};  ///< Mount in base_footprint (ari_robot's URDF: front fisheye at x -0.142).
  double y_m{0.0};
  double z_m{1.321};                 ///< Height, for image regions only.
  double field_of_view_deg{180.0};   ///< Horizontal.
  double range_m{10.0};              ///< Bodies farther away are not tracked.
  double min_visible_fraction{0.2};  ///< Below this share of unblocked rays a body is occluded.

  template <class V>
  void visit(V& v) {
    v.field("x", x_m);
    v.field("y", y_m);
    v.field("z", z_m, core::non_negative());
    v.field("field_of_view_deg", field_of_view_deg, {0.0, 360.0, true});
    v.field("range", range_m, core::positive());
    v.field("min_visible_fraction", min_visible_fraction, {0.0, 1.0, true});
  }
};

/// The head camera that sees faces (D6.4 §3.5.3: 62 degrees), turning with the head pan.
struct FaceCameraConfig {
  double pan_axis_x_m{-0.2255};  ///< head_1_joint in base_footprint (ari_robot's URDF).
  double pan_axis_y_m{0.0};
  double x_m{0.1055};  ///< Camera ahead of the pan axis (head_front_camera at x -0.120 at pan 0).
  double y_m{0.0};
  double z_m{1.591};
  double field_of_view_deg{62.0};
  double range_m{2.0};               ///< ARI's face detection: about 2 m (ARI documentation).
  double min_visible_fraction{0.5};  ///< A face needs most of the head in view.
  double max_face_angle_deg{60.0};   ///< Face seen when turned toward the camera within this.

  template <class V>
  void visit(V& v) {
    v.field("pan_axis_x", pan_axis_x_m);
    v.field("pan_axis_y", pan_axis_y_m);
    v.field("x", x_m);
    v.field("y", y_m);
    v.field("z", z_m, core::non_negative());
    v.field("field_of_view_deg", field_of_view_deg, {0.0, 360.0, true});
    v.field("range", range_m, core::positive());
    v.field("min_visible_fraction", min_visible_fraction, {0.0, 1.0, true});
    v.field("max_face_angle_deg", max_face_angle_deg, core::between(0.0, 180.0));
  }
};

/// The ReSpeaker array in the torso (D6.4 §3.5.4): hears speakers within a distance, not through
/// walls.
struct MicrophoneConfig {
  double x_m{-0.122};  ///< torso_mic_front_link in base_footprint.
  double y_m{0.0};
  double max_distance_m{5.0};   ///< D6.4 §3.5.4: max listening distance d.
  double voice_timeout_s{2.0};  ///< A voice stays tracked this long after its last word.
  std::string language{"en-GB"};

  template <class V>
  void visit(V& v) {
    v.field("x", x_m);
    v.field("y", y_m);
    v.field("max_distance", max_distance_m, core::positive());
    v.field("voice_timeout", voice_timeout_s, core::non_negative());
    v.field("language", language);
  }
};

/// How sight is blocked: rays against the occupancy grid and against people as circles.
struct OcclusionConfig {
  int rays_per_person{9};       ///< Rays spread over a person's width; visible fraction = share.
  double person_radius_m{0.2};  ///< Matches the world's body radius.
  int occupied_threshold{50};   ///< Grid cells at or above this value block sight.

  template <class V>
  void visit(V& v) {
    v.field("rays_per_person", rays_per_person, core::between(1.0, 101.0));
    v.field("person_radius", person_radius_m, core::positive());
    v.field("occupied_threshold", occupied_threshold, core::between(1.0, 100.0));
  }
};

/// The 2D world has no heights or heads; these place the 3D frames and turn the head.
struct HumanModelConfig {
  double hip_height_m{0.95};  ///< body_<id> origin (mid-hips).
  double eye_height_m{1.60};  ///< face_<id>, gaze_<id> and person_<id> origin (sellion).
  /// The head (face_<id>) turns toward the gaze direction by at most this much from the body.
  double head_turn_limit_deg{60.0};

  template <class V>
  void visit(V& v) {
    v.field("hip_height", hip_height_m, core::positive());
    v.field("eye_height", eye_height_m, core::positive());
    v.field("head_turn_limit_deg", head_turn_limit_deg, core::between(0.0, 180.0));
  }
};

/// Missed detections and re-identification errors of one tracker (bodies or faces).
struct DetectionErrors {
  double miss_rate{0.02};  ///< Per frame, close, centred and fully visible.
  /// Extra per-frame miss probability reached at the sensor's range, rising linearly from 0 m.
  double miss_rate_at_max_range{0.10};
  /// Extra miss probability at the edge of the field of view, rising linearly over the band.
  double miss_rate_at_fov_border{0.30};
  double fov_border_deg{10.0};  ///< Width of that band inside each edge.
  /// Extra miss probability at the sensor's minimum visible fraction, falling linearly to 0 at
  /// fully visible.
  double miss_rate_occluded{0.30};
  double reid_after_occlusion{0.2};    ///< New id when re-found after an occlusion.
  double reid_after_leaving_fov{0.5};  ///< New id when re-found after leaving the view.
  double reid_rate_per_min{0.2};       ///< Spontaneous id switches per minute tracked.

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("miss_rate", miss_rate, probability);
    v.field("miss_rate_at_max_range", miss_rate_at_max_range, probability);
    v.field("miss_rate_at_fov_border", miss_rate_at_fov_border, probability);
    v.field("fov_border_deg", fov_border_deg, core::non_negative());
    v.field("miss_rate_occluded", miss_rate_occluded, probability);
    v.field("reid_after_occlusion", reid_after_occlusion, probability);
    v.field("reid_after_leaving_fov", reid_after_leaving_fov, probability);
    v.field("reid_rate_per_min", reid_rate_per_min, core::non_negative());
  }
};

/// Gaussian noise on a perceived pose, its standard deviation growing linearly with distance.
struct PoseNoise {
  double position_noise_m{0.03};      ///< Standard deviation per axis at 0 m.
  double position_noise_per_m{0.02};  ///< Added per metre of distance.
  double orientation_noise_deg{3.0};  ///< Standard deviation at 0 m.
  double orientation_noise_deg_per_m{2.0};

  double position_stddev_m(double distance_m) const {
    return position_noise_m + position_noise_per_m * distance_m;
  }
  double orientation_stddev_deg(double distance_m) const {
    return orientation_noise_deg + orientation_noise_deg_per_m * distance_m;
  }

  template <class V>
  void visit(V& v) {
    v.field("position_noise", position_noise_m, core::non_negative());
    v.field("position_noise_per_m", position_noise_per_m, core::non_negative());
    v.field("orientation_noise_deg", orientation_noise_deg, core::non_negative());
    v.field("orientation_noise_deg_per_m", orientation_noise_deg_per_m, core::non_negative());
  }
};

/// Rows: the true emotion; columns: the probability of perceiving neutral, happy, angry,
/// disturbed. Each row sums to 1; the identity is error-free.
struct EmotionConfusion {
  std::vector<double> neutral{0.90, 0.04, 0.03, 0.03};
  std::vector<double> happy{0.10, 0.88, 0.01, 0.01};
  std::vector<double> angry{0.08, 0.01, 0.81, 0.10};
  std::vector<double> disturbed{0.12, 0.01, 0.10, 0.77};

  const std::vector<double>& row(model::Emotion truth) const;
  static EmotionConfusion identity();

  template <class V>
  void visit(V& v) {
    v.field("neutral", neutral, core::between(0.0, 1.0));
    v.field("happy", happy, core::between(0.0, 1.0));
    v.field("angry", angry, core::between(0.0, 1.0));
    v.field("disturbed", disturbed, core::between(0.0, 1.0));
  }
};

struct BodyErrors {
  DetectionErrors detection;
  PoseNoise pose;

  template <class V>
  void visit(V& v) {
    detection.visit(v);
    pose.visit(v);
  }
};

struct FaceErrors {
  DetectionErrors detection;
  PoseNoise pose{0.03, 0.02, 5.0, 2.0};
  double age_noise_years{5.0};     ///< Standard deviation of the perceived age.
  double gender_error_rate{0.05};  ///< Probability of reporting one of the other genders.
  double mask_error_rate{0.05};    ///< Probability of reporting the opposite of the truth.
  EmotionConfusion emotion_confusion;

  template <class V>
  void visit(V& v) {
    detection.visit(v);
    pose.visit(v);
    v.field("age_noise_years", age_noise_years, core::non_negative());
    v.field("gender_error_rate", gender_error_rate, core::between(0.0, 1.0));
    v.field("mask_error_rate", mask_error_rate, core::between(0.0, 1.0));
    v.section("emotion_confusion", emotion_confusion);
  }
};

/// Automatic speech recognition errors: each heard word is substituted or deleted, and a word
/// inserted after it, so that the expected word error rate (S + D + I) / N is `word_error_rate`,
/// split by the three shares (summing to 1).
struct SpeechErrors {
  double word_error_rate{0.10};
  double substitution_share{0.60};
  double deletion_share{0.25};
  double insertion_share{0.15};
  /// Probability that an utterance is attributed to another audible person's voice.
  double misattribution_rate{0.05};
  /// Words that substitutions and insertions draw from.
  std::vector<std::string> vocabulary{"the", "a",    "to",   "and",  "yes",    "no",     "is",
                                      "it",  "you",  "we",   "what", "where",  "here",   "there",
                                      "can", "help", "room", "time", "doctor", "please", "okay"};

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("word_error_rate", word_error_rate, probability);
    v.field("substitution_share", substitution_share, probability);
    v.field("deletion_share", deletion_share, probability);
    v.field("insertion_share", insertion_share, probability);
    v.field("misattribution_rate", misattribution_rate, probability);
    v.field("vocabulary", vocabulary);
  }
};

/// Person bookkeeping as hri_person_manager does it.
struct PersonConfig {
  double location_decay_s{10.0};  ///< location_confidence falls from 1 to 0 over this once unseen.
  /// s of sim time after which a person unseen (no face, body or voice) is forgotten: no longer
  /// known, its per-person state released. Much longer than location_decay, so that a person
  /// reported at confidence 0 stays known for a while, as hri_person_manager keeps them; a
  /// forgotten human seen again is a person again, under the same id in the "human" style.
  double forget_after_s{60.0};
  /// How person ids look: "human" gives simulated human N the id `human<N>`, as if ARI recognised
  /// everyone from a database; "random" gives each a seeded random id (`anonymous_person_` and
  /// five letters), as a person manager names the persons it makes up, so that consumers can be
  /// tested for relying on no naming at all.
  std::string id_style{"human"};
  /// Outer edges of the proxemic zones, measured from ARI's base to the person (hri_person_manager
  /// 1.1.0's defaults, after Hall's zones).
  double personal_distance_m{1.2};
  double social_distance_m{3.6};
  double public_distance_m{20.0};

  template <class V>
  void visit(V& v) {
    v.field("location_decay", location_decay_s, core::positive());
    v.field("forget_after", forget_after_s, core::positive());
    v.field("id_style", id_style);
    v.field("personal_distance", personal_distance_m, core::positive());
    v.field("social_distance", social_distance_m, core::positive());
    v.field("public_distance", public_distance_m, core::positive());
  }
};

/// What ROS4HRI's matchers send on /humans/candidate_matches in detectors mode
/// (CandidateMatcher): confidences of true matches, before noise.
struct MatcherConfig {
  double face_body_confidence{0.9};    ///< hri_face_body_matcher, body -> face.
  double recognition_rate{0.95};       ///< Share of face tracks the face identifier recognises.
  double recognition_confidence{0.9};  ///< Face identifier, person -> face.
  double voice_body_confidence{0.8};   ///< Speaker localiser, body -> voice.
  double confidence_noise{0.05};       ///< Standard deviation added to each match, per frame.
  /// Matches at or below are not sent (hri_face_body_matcher's confidence_threshold).
  double threshold{0.5};

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("face_body_confidence", face_body_confidence, probability);
    v.field("recognition_rate", recognition_rate, probability);
    v.field("recognition_confidence", recognition_confidence, probability);
    v.field("voice_body_confidence", voice_body_confidence, probability);
    v.field("confidence_noise", confidence_noise, core::between(0.0, 1.0));
    v.field("threshold", threshold, core::between(0.0, 1.0));
  }
};

/// Visual social engagement (Webb & Lemaignan, RO-MAN 2022) as hri_engagement computes it.
struct EngagementConfig {
  double max_distance_m{4.0};           ///< Farther people score 0.
  double field_of_attention_deg{60.0};  ///< Of both ARI and the person, for mutual gaze.
  double threshold{0.5};                ///< Score above which a frame counts as engaged.
  double window_s{10.0};                ///< Observation window of the level.

  template <class V>
  void visit(V& v) {
    v.field("max_distance", max_distance_m, core::positive());
    // tan(90 deg) is infinite: the field of attention stays below a right angle.
    v.field("field_of_attention_deg", field_of_attention_deg, {0.0, 89.0, true});
    v.field("threshold", threshold, core::between(0.0, 1.0));
    v.field("window", window_s, core::positive());
  }
};

/// GCFF on the perceived bodies (metres).
struct GroupConfig {
  GcffParams gcff{0.6, 0.8};
  /// A group not seen is remembered this many frames, so that one whose members were missed
  /// for a moment keeps its id (GroupTracker).
  int id_memory_frames{30};
  /// Two people count as together when GCFF grouped them in most of this many frames
  /// (MembershipFilter); 1 reports GCFF's grouping of each frame as it is.
  int membership_window_frames{10};

  template <class V>
  void visit(V& v) {
    v.field("stride", gcff.stride, core::positive());
    v.field("mdl", gcff.mdl, core::positive());
    v.field("id_memory_frames", id_memory_frames, core::between(0.0, 10000.0));
    v.field("membership_window_frames", membership_window_frames, core::between(1.0, 10000.0));
  }
};

/// Everything ARI's simulated perception is configured with.
struct PerceptionConfig {
  unsigned seed{1};           ///< Every random draw of the perception derives from it.
  bool errors_enabled{true};  ///< false: every error model off, the output is ground truth.
  BodyCameraConfig body_camera;
  FaceCameraConfig face_camera;
  MicrophoneConfig microphone;
  OcclusionConfig occlusion;
  HumanModelConfig human_model;
  BodyErrors body_errors;
  FaceErrors face_errors;
  SpeechErrors speech_errors;
  PersonConfig persons;
  MatcherConfig matchers;
  EngagementConfig engagement;
  GroupConfig groups;

  template <class V>
  void visit(V& v) {
    v.field("seed", seed);
    v.field("errors_enabled", errors_enabled);
    v.section("body_camera", body_camera);
    v.section("face_camera", face_camera);
    v.section("microphone", microphone);
    v.section("occlusion", occlusion);
    v.section("human_model", human_model);
    v.section("body_errors", body_errors);
    v.section("face_errors", face_errors);
    v.section("speech_errors", speech_errors);
    v.section("persons", persons);
    v.section("matchers", matchers);
    v.section("engagement", engagement);
    v.section("groups", groups);
  }

  /// Throws core::ConfigError naming the first bad field (`body_errors.miss_rate: expected a
  /// number [0, 1], got 1.5`): bounds of every field, confusion rows of 4 summing to 1, speech
  /// shares summing to 1, a vocabulary of single words when words are substituted or inserted.
  void validate() const;

  /// This configuration with every error model off (zero rates and noise, identity confusion).
  PerceptionConfig without_errors() const;
  /// The error models in effect: these, or none when errors_enabled is false.
  PerceptionConfig effective() const { return errors_enabled ? *this : without_errors(); }

  /// Reads a mapping (every field optional, unknown keys rejected) and validates it. Errors name
  /// the source and the field path.
  static PerceptionConfig from_yaml(const core::YamlMap& map);
  static PerceptionConfig load_file(const std::string& path);
  /// The configuration as YAML text that from_yaml reads back to the same values.
  std::string to_yaml() const;
};

}  // namespace ari_social_sim::perception
