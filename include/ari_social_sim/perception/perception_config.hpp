#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/ari_sensor_geometry.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/model/person_attributes.hpp"
#include "ari_social_sim/perception/gcff.hpp"
#include "ari_social_sim/world/posture.hpp"

// Parameters of ARI's simulated perception (docs/perception.md). Defaults are ARI's sensors
// (ari_robot's URDF, D6.4 §3.5) and moderate error levels; config/perception.yaml spells them out.
// Each struct lists its fields once in `visit` (core/config_fields.hpp), which reads, checks,
// writes and documents them. Angles are in degrees where the name says `_deg`, lengths in metres,
// rates are probabilities per event unless the name gives a unit.

namespace ari_social_sim::perception {

/// The torso front fisheye that tracks bodies. Mount and lens default to ARI's
/// (model/ari_sensor_geometry.hpp, which the rendered cameras use too).
struct BodyCameraConfig {
  double x_m{model::kFrontFisheyeInFootprint.x_m};
  double y_m{model::kFrontFisheyeInFootprint.y_m};
  double z_m{model::kFrontFisheyeInFootprint.z_m};
  double field_of_view_deg{model::kFisheyeCamera.hfov_deg};
  double range_m{10.0};
  double min_visible_fraction{0.2};

  template <class V>
  void visit(V& v) {
    v.field("x", x_m, "m, mount in base_footprint");
    v.field("y", y_m, "m, mount in base_footprint");
    v.field("z", z_m, "m, height, for image regions only", core::non_negative());
    v.field("field_of_view_deg", field_of_view_deg, "horizontal", core::Bounds{0.0, 360.0, true});
    v.field("range", range_m, "m; bodies farther away are not tracked", core::positive());
    v.field("min_visible_fraction", min_visible_fraction,
            "share of rays that must reach a body past obstacles; below it the body is occluded",
            core::Bounds{0.0, 1.0, true});
  }
};

/// The head camera that sees faces, turning with the head pan. Mount and lens default to ARI's
/// (model/ari_sensor_geometry.hpp, which the rendered head camera uses too).
struct FaceCameraConfig {
  double pan_axis_x_m{model::kHeadPanJointInBaseLink.x_m};
  double pan_axis_y_m{model::kHeadPanJointInBaseLink.y_m};
  double x_m{model::head_camera_ahead_of_pan_axis_m()};
  double y_m{0.0};  // the camera is on the head's centre line
  double z_m{model::head_camera_height_m()};
  double field_of_view_deg{model::kHeadCamera.hfov_deg};
  double range_m{2.0};  // about 2 m (ARI documentation)
  double min_visible_fraction{0.5};
  double max_face_angle_deg{60.0};

  template <class V>
  void visit(V& v) {
    v.field("pan_axis_x", pan_axis_x_m, "m, head_1_joint in base_footprint");
    v.field("pan_axis_y", pan_axis_y_m, "m, head_1_joint in base_footprint");
    v.field("x", x_m, "m, camera ahead of the pan axis");
    v.field("y", y_m, "m, camera beside the pan axis");
    v.field("z", z_m, "m, height", core::non_negative());
    v.field("field_of_view_deg", field_of_view_deg, "horizontal", core::Bounds{0.0, 360.0, true});
    v.field("range", range_m, "m; ARI's face detection reaches about 2 m", core::positive());
    v.field("min_visible_fraction", min_visible_fraction,
            "share of rays that must reach the head: a face needs most of it in view",
            core::Bounds{0.0, 1.0, true});
    v.field("max_face_angle_deg", max_face_angle_deg,
            "a face is seen when turned toward the camera within this", core::between(0.0, 180.0));
  }
};

/// The ReSpeaker array in the torso (D6.4 §3.5.4): hears speakers within a distance, not through
/// walls.
struct MicrophoneConfig {
  double x_m{model::kMicrophoneInFootprint.x_m};
  double y_m{model::kMicrophoneInFootprint.y_m};
  double max_distance_m{5.0};
  double voice_timeout_s{2.0};
  std::string language{"en-GB"};

  template <class V>
  void visit(V& v) {
    v.field("x", x_m, "m, torso_mic_front_link in base_footprint");
    v.field("y", y_m, "m, torso_mic_front_link in base_footprint");
    v.field("max_distance", max_distance_m, "m, farthest speaker heard", core::positive());
    v.field("voice_timeout", voice_timeout_s, "s a voice stays tracked after its last word",
            core::non_negative());
    v.field("language", language, "LiveSpeech.language");
  }
};

/// How sight is blocked: rays against the occupancy grid and against people as circles.
struct OcclusionConfig {
  int rays_per_person{9};
  double person_radius_m{0.2};  // the world's body radius
  int occupied_threshold{50};

  template <class V>
  void visit(V& v) {
    v.field("rays_per_person", rays_per_person,
            "rays spread over a person's width; visible fraction = share reaching them",
            core::between(1.0, 101.0));
    v.field("person_radius", person_radius_m, "m; people block sight as circles of this radius",
            core::positive());
    v.field("occupied_threshold", occupied_threshold,
            "/map cells at or above this value block sight (and sound)", core::between(1.0, 100.0));
  }
};

/// The 2D world has no heights or heads; these place the 3D frames and turn the head.
struct HumanModelConfig {
  double hip_height_m{0.95};
  double eye_height_m{1.60};
  // Seated on a 0.45 m seat: hips about 0.1 m above it, eyes about 0.75 m (sitting eye height of
  // adults, docs/cameras.md "Seated figures").
  double seated_hip_height_m{0.55};
  double seated_eye_height_m{1.20};
  double head_turn_limit_deg{60.0};

  double hip_height(world::Posture posture) const {
    return posture == world::Posture::kSitting ? seated_hip_height_m : hip_height_m;
  }
  double eye_height(world::Posture posture) const {
    return posture == world::Posture::kSitting ? seated_eye_height_m : eye_height_m;
  }

  template <class V>
  void visit(V& v) {
    v.field("hip_height", hip_height_m, "m, body_<id> origin (mid-hips)", core::positive());
    v.field("eye_height", eye_height_m, "m, face_<id>, gaze_<id> and person_<id> origin",
            core::positive());
    v.field("head_turn_limit_deg", head_turn_limit_deg,
            "the face turns toward the gaze by at most this from the body",
            core::between(0.0, 180.0));
    v.rule("eye_height", eye_height_m > hip_height_m,
           "more than hip_height (" + core::number_text(hip_height_m) + ")",
           core::number_text(eye_height_m));
    v.field("seated_hip_height", seated_hip_height_m, "m, body_<id> origin of a seated person",
            core::positive());
    v.field("seated_eye_height", seated_eye_height_m,
            "m, face_<id>, gaze_<id> and head_<id> origin of a seated person", core::positive());
    v.rule("seated_eye_height", seated_eye_height_m > seated_hip_height_m,
           "more than seated_hip_height (" + core::number_text(seated_hip_height_m) + ")",
           core::number_text(seated_eye_height_m));
  }
};

/// Missed detections and re-identification errors of one tracker (bodies or faces).
struct DetectionErrors {
  double miss_rate{0.02};
  double miss_rate_at_max_range{0.10};
  double miss_rate_at_fov_border{0.30};
  double fov_border_deg{10.0};
  double miss_rate_occluded{0.30};
  double reid_after_occlusion{0.2};
  double reid_after_leaving_fov{0.5};
  double reid_rate_per_min{0.2};

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("miss_rate", miss_rate, "per frame, close, centred and fully visible", probability);
    v.field("miss_rate_at_max_range", miss_rate_at_max_range,
            "extra per-frame miss probability at the sensor's range, rising linearly from 0 m",
            probability);
    v.field("miss_rate_at_fov_border", miss_rate_at_fov_border,
            "extra miss probability at the edge of the view, rising linearly over the border band",
            probability);
    v.field("fov_border_deg", fov_border_deg, "width of that band inside each edge",
            core::non_negative());
    v.field("miss_rate_occluded", miss_rate_occluded,
            "extra miss probability at min_visible_fraction, falling linearly to 0 at fully "
            "visible",
            probability);
    v.field("reid_after_occlusion", reid_after_occlusion, "new id when re-found after an occlusion",
            probability);
    v.field("reid_after_leaving_fov", reid_after_leaving_fov,
            "new id when re-found after leaving the view", probability);
    v.field("reid_rate_per_min", reid_rate_per_min, "spontaneous id switches per minute tracked",
            core::non_negative());
  }
};

/// Gaussian noise on a perceived pose, its standard deviation growing linearly with distance.
struct PoseNoise {
  double position_noise_m{0.03};
  double position_noise_per_m{0.02};
  double orientation_noise_deg{3.0};
  double orientation_noise_deg_per_m{2.0};

  double position_stddev_m(double distance_m) const {
    return position_noise_m + position_noise_per_m * distance_m;
  }
  double orientation_stddev_deg(double distance_m) const {
    return orientation_noise_deg + orientation_noise_deg_per_m * distance_m;
  }

  template <class V>
  void visit(V& v) {
    v.field("position_noise", position_noise_m, "m, standard deviation per axis at 0 m",
            core::non_negative());
    v.field("position_noise_per_m", position_noise_per_m, "added per metre of distance",
            core::non_negative());
    v.field("orientation_noise_deg", orientation_noise_deg, "standard deviation at 0 m",
            core::non_negative());
    v.field("orientation_noise_deg_per_m", orientation_noise_deg_per_m,
            "added per metre of distance", core::non_negative());
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
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("neutral", neutral, "P(perceived emotion) when neutral", probability);
    v.field("happy", happy, "P(perceived emotion) when happy", probability);
    v.field("angry", angry, "P(perceived emotion) when angry", probability);
    v.field("disturbed", disturbed, "P(perceived emotion) when disturbed", probability);
    for (const auto& [name, row] :
         {std::pair{"neutral", &neutral}, std::pair{"happy", &happy}, std::pair{"angry", &angry},
          std::pair{"disturbed", &disturbed}}) {
      v.rule(name, is_distribution(*row),
             "4 probabilities (neutral, happy, angry, disturbed) summing to 1",
             distribution_problem(*row));
    }
  }

 private:
  static bool is_distribution(const std::vector<double>& row);
  /// What keeps `row` from being a distribution: its length, or else its sum.
  static std::string distribution_problem(const std::vector<double>& row);
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
  double age_noise_years{5.0};
  double gender_error_rate{0.05};
  double mask_error_rate{0.05};
  EmotionConfusion emotion_confusion;

  template <class V>
  void visit(V& v) {
    detection.visit(v);
    pose.visit(v);
    v.field("age_noise_years", age_noise_years, "standard deviation of the perceived age",
            core::non_negative());
    v.field("gender_error_rate", gender_error_rate,
            "probability of reporting one of the other genders", core::between(0.0, 1.0));
    v.field("mask_error_rate", mask_error_rate,
            "probability of reporting the opposite of the truth", core::between(0.0, 1.0));
    v.section("emotion_confusion", emotion_confusion,
              "true emotion -> P(neutral, happy, angry, disturbed)");
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
  double misattribution_rate{0.05};
  std::vector<std::string> vocabulary{"the", "a",    "to",   "and",  "yes",    "no",     "is",
                                      "it",  "you",  "we",   "what", "where",  "here",   "there",
                                      "can", "help", "room", "time", "doctor", "please", "okay"};

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("word_error_rate", word_error_rate,
            "expected (substitutions + deletions + insertions) / words", probability);
    v.field("substitution_share", substitution_share, "share of errors that substitute a word",
            probability);
    v.field("deletion_share", deletion_share, "share that delete one", probability);
    v.field("insertion_share", insertion_share, "share that insert one", probability);
    v.field("misattribution_rate", misattribution_rate,
            "probability that an utterance is given to another audible person's voice",
            probability);
    v.field("vocabulary", vocabulary, "words that substitutions and insertions draw from");
    const double shares = substitution_share + deletion_share + insertion_share;
    v.rule("substitution_share", std::abs(shares - 1.0) <= 1e-6,
           "substitution_share + deletion_share + insertion_share = 1", core::number_text(shares));
    const bool draws_words = word_error_rate > 0.0 && substitution_share + insertion_share > 0.0;
    v.rule("vocabulary", !draws_words || distinct_words() >= 2,
           "at least two different words (substitutions and insertions draw from it)",
           std::to_string(distinct_words()));
    v.rule("vocabulary", compound_word().empty(), "single words", "'" + compound_word() + "'");
  }

 private:
  size_t distinct_words() const;
  /// The first entry of the vocabulary that is not one word (empty or with a space), or "".
  std::string compound_word() const;
};

/// Person bookkeeping as hri_person_manager does it.
struct PersonConfig {
  /// The values of id_style, as messages list them.
  static constexpr const char* kIdStyles = "human or random";
  static bool is_id_style(const std::string& style) {
    return style == "human" || style == "random";
  }

  double location_decay_s{10.0};
  double forget_after_s{60.0};
  std::string id_style{"human"};
  double personal_distance_m{1.2};
  double social_distance_m{3.6};
  double public_distance_m{20.0};

  template <class V>
  void visit(V& v) {
    v.field("location_decay", location_decay_s,
            "s for location_confidence to fall from 1 to 0 once unseen", core::positive());
    // Much longer than location_decay, so that a person reported at confidence 0 stays known
    // for a while, as hri_person_manager keeps them.
    v.field("forget_after", forget_after_s,
            "s of sim time unseen (no face, body or voice) after which a person is forgotten; "
            "seen again, they are a person again, under the same id with id_style human",
            core::positive());
    // "random" lets consumers be tested for relying on no naming at all.
    v.field("id_style", id_style,
            "human: human N is `human<N>`, as if ARI recognised everyone; random: "
            "`anonymous_person_` and five seeded letters, as a person manager names the persons "
            "it makes up");
    v.field("personal_distance", personal_distance_m,
            "m from ARI's base: outer edge of the personal zone (hri_person_manager 1.1.0, after "
            "Hall)",
            core::positive());
    v.field("social_distance", social_distance_m, "m: of the social zone", core::positive());
    v.field("public_distance", public_distance_m, "m: of the public zone; farther is unknown",
            core::positive());
    v.rule("id_style", is_id_style(id_style), kIdStyles, "'" + id_style + "'");
    v.rule("forget_after", forget_after_s >= location_decay_s,
           "at least location_decay (" + core::number_text(location_decay_s) + ")",
           core::number_text(forget_after_s));
    v.rule("social_distance",
           personal_distance_m < social_distance_m && social_distance_m < public_distance_m,
           "personal_distance < social_distance < public_distance",
           core::number_text(personal_distance_m) + ", " + core::number_text(social_distance_m) +
               ", " + core::number_text(public_distance_m));
  }
};

/// What ROS4HRI's matchers send on /humans/candidate_matches in detectors mode
/// (CandidateMatcher): confidences of true matches, before noise.
struct MatcherConfig {
  double face_body_confidence{0.9};
  double recognition_rate{0.95};
  double recognition_confidence{0.9};
  double voice_body_confidence{0.8};
  double confidence_noise{0.05};
  double threshold{0.5};

  template <class V>
  void visit(V& v) {
    const core::Bounds probability = core::between(0.0, 1.0);
    v.field("face_body_confidence", face_body_confidence,
            "body -> face of the same human (hri_face_body_matcher)", probability);
    v.field("recognition_rate", recognition_rate,
            "share of face tracks the face identifier recognises", probability);
    v.field("recognition_confidence", recognition_confidence,
            "person -> face (hri_face_identification)", probability);
    v.field("voice_body_confidence", voice_body_confidence,
            "body -> voice of the same human (a speaker localiser)", probability);
    v.field("confidence_noise", confidence_noise,
            "standard deviation added to each confidence, per frame", core::between(0.0, 1.0));
    v.field("threshold", threshold,
            "matches at or below are not sent (hri_face_body_matcher's confidence_threshold)",
            core::between(0.0, 1.0));
  }
};

/// Visual social engagement (Webb & Lemaignan, RO-MAN 2022) as hri_engagement computes it.
struct EngagementConfig {
  double max_distance_m{4.0};
  double field_of_attention_deg{60.0};
  double threshold{0.5};
  double window_s{10.0};

  template <class V>
  void visit(V& v) {
    v.field("max_distance", max_distance_m, "m; farther people score 0", core::positive());
    // tan(90 deg) is infinite: the field of attention stays below a right angle.
    v.field("field_of_attention_deg", field_of_attention_deg,
            "of both ARI and the person, for mutual gaze", core::Bounds{0.0, 89.0, true});
    v.field("threshold", threshold, "score above which a frame counts as engaged",
            core::between(0.0, 1.0));
    v.field("window", window_s, "s of history behind the level", core::positive());
  }
};

/// GCFF on the perceived bodies (metres).
struct GroupConfig {
  GcffParams gcff{0.6, 0.8};
  int id_memory_frames{30};
  int membership_window_frames{10};

  template <class V>
  void visit(V& v) {
    gcff.visit(v);
    // GroupTracker: a group whose members were missed for a moment keeps its id.
    v.field("id_memory_frames", id_memory_frames,
            "a group unseen this many frames keeps its id when it returns",
            core::between(0.0, 10000.0));
    v.field("membership_window_frames", membership_window_frames,
            "two people are together when GCFF grouped them in most of this many frames "
            "(MembershipFilter); 1 reports each frame's grouping as it is",
            core::between(1.0, 10000.0));
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
};

/// Everything ARI's simulated perception is configured with (config/perception.yaml).
struct PerceptionConfig {
  uint64_t seed{1};
  bool errors_enabled{true};
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
    v.field("seed", seed, "every random draw of the perception derives from it");
    v.field("errors_enabled", errors_enabled,
            "false: every error model off, the output equals the ground truth");
    v.section("body_camera", body_camera, "torso front fisheye (ELP IMX179), tracks bodies");
    v.section("face_camera", face_camera, "head camera (62.2 degrees), turns with head_1_joint");
    v.section("microphone", microphone, "ReSpeaker array in the torso");
    v.section("occlusion", occlusion, "what blocks sight");
    v.section("human_model", human_model, "the 2D world has no heights: where the 3D frames go");
    v.section("body_errors", body_errors, "body tracker: misses, id switches, pose noise");
    v.section("face_errors", face_errors,
              "face tracker: misses, id switches, pose noise, soft biometrics");
    v.section("speech_errors", speech_errors, "speech recognition errors");
    v.section("persons", persons, "person bookkeeping, as hri_person_manager");
    v.section("matchers", matchers,
              "detectors mode: what ROS4HRI's matchers send on /humans/candidate_matches");
    v.section("engagement", engagement, "hri_engagement's visual social engagement");
    v.section("groups", groups, "GCFF on the perceived bodies (group_detection_node)");
  }

  /// Throws core::ConfigError naming the first bad field (`PerceptionConfig:
  /// body_errors.miss_rate: expected a number [0, 1], got 1.5`): the bounds and rules of visit.
  void validate() const;

  /// This configuration with every error model off (zero rates and noise, identity confusion).
  PerceptionConfig without_errors() const;
  /// The error models in effect: these, or none when errors_enabled is false.
  PerceptionConfig effective() const { return errors_enabled ? *this : without_errors(); }

  /// Reads a mapping (every field optional, unknown keys rejected), checking what validate()
  /// checks. Errors name the source and the field path.
  static PerceptionConfig from_yaml(const core::YamlMap& map);
  static PerceptionConfig load_file(const std::string& path);
  /// The configuration as YAML text that from_yaml reads back to the same values.
  std::string to_yaml() const;
};

}  // namespace ari_social_sim::perception
