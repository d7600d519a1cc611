#include "ari_social_sim/perception/face_tracker.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/perception/image_regions.hpp"
#include "ari_social_sim/perception/pose_noise.hpp"

namespace ari_social_sim::perception {
namespace {

// Face size for the image region (an adult face, chin to hairline, ear to ear), and how far its
// centre is below the eyes: the hairline about 8 cm above them, the chin about 12 cm below
// (Farkas 1994's adult means), as the figures in the cameras draw it.
constexpr double kFaceWidth_m = 0.16;
constexpr double kFaceHeight_m = 0.20;
constexpr double kFaceCentreBelowEyes_m = 0.02;
// The oldest age a face analyser reports; hri_msgs/SoftBiometrics.age is a uint8.
constexpr double kMaxAge_years = 120.0;

model::Gender other_gender(model::Gender truth, core::Rng& rng) {
  // The two genders that are not the true one, in enum order.
  constexpr model::Gender kAll[] = {model::Gender::kFemale, model::Gender::kMale,
                                    model::Gender::kNonIdentified};
  model::Gender others[2];
  size_t count = 0;
  for (model::Gender gender : kAll) {
    if (gender != truth) {
      others[count++] = gender;
    }
  }
  return others[rng.uniform_index(2)];
}

}  // namespace

double head_direction(const world::HumanSnapshot& human, double head_turn_limit_rad) {
  const double turn = core::angle_difference(human.gaze.direction_rad, human.pose.theta);
  return core::wrap_angle(human.pose.theta +
                          std::clamp(turn, -head_turn_limit_rad, head_turn_limit_rad));
}

FaceTracker::FaceTracker(const PerceptionConfig& config, TransientIds& ids, core::Rng rng)
    : config_(config),
      track_ids_(config.face_errors.detection, ids, core::Rng(rng.next_u64())),
      rng_(rng) {}

void FaceTracker::analyse(const world::HumanSnapshot& human, PerceivedFace& face) {
  const FaceErrors& errors = config_.face_errors;
  face.age_years = human.age_years;
  if (errors.age_noise_years > 0.0) {
    face.age_years = std::clamp(
        std::round(human.age_years + rng_.normal(0.0, errors.age_noise_years)), 0.0, kMaxAge_years);
  }
  // Confidences are what the configured error levels make of a single estimate.
  face.age_confidence = std::exp(-errors.age_noise_years / 10.0);
  face.gender = human.gender;
  if (errors.gender_error_rate > 0.0 && rng_.bernoulli(errors.gender_error_rate)) {
    face.gender = other_gender(human.gender, rng_);
  }
  face.gender_confidence = 1.0 - errors.gender_error_rate;
  face.mask = human.mask;
  if (errors.mask_error_rate > 0.0 && rng_.bernoulli(errors.mask_error_rate)) {
    face.mask = !face.mask;
  }
  face.mask_confidence = 1.0 - errors.mask_error_rate;
  const std::vector<double>& row = errors.emotion_confusion.row(human.emotion);
  face.emotion = human.emotion;
  if (row[static_cast<size_t>(human.emotion)] < 1.0) {
    face.emotion = static_cast<model::Emotion>(rng_.categorical(row));
  }
  face.emotion_confidence =
      errors.emotion_confusion.row(face.emotion)[static_cast<size_t>(face.emotion)];
}

void FaceTracker::update(const world::WorldSnapshot& snapshot, const AriSensors& sensors,
                         const SightObstacles& obstacles, double dt_s,
                         std::vector<PerceivedFace>& faces) {
  const FieldOfView& camera = sensors.face_camera;
  const FaceCameraConfig& camera_config = config_.face_camera;
  const double turn_limit = core::deg_to_rad(config_.human_model.head_turn_limit_deg);
  const double max_face_angle = core::deg_to_rad(camera_config.max_face_angle_deg);
  for (size_t i = 0; i < snapshot.humans.size(); ++i) {
    const world::HumanSnapshot& human = snapshot.humans[i];
    const Eigen::Vector2d& position = human.pose.position;
    const double head = head_direction(human, turn_limit);
    const Eigen::Vector2d to_camera = camera.X_map_sensor.position - position;
    const bool facing = std::abs(core::angle_difference(std::atan2(to_camera.y(), to_camera.x()),
                                                        head)) <= max_face_angle;
    const bool in_view = camera.contains(position);
    Sighting sighting = Sighting::kOccluded;
    if (!in_view || facing) {
      const double visible =
          in_view ? visible_fraction(camera, obstacles, i, config_.occlusion.rays_per_person) : 0.0;
      sighting = decide_sighting(config_.face_errors.detection, camera, position, visible,
                                 camera_config.min_visible_fraction, rng_);
    }
    const std::string* face_id = track_ids_.update(human.id, sighting, dt_s);
    if (face_id == nullptr) {
      continue;
    }
    PerceivedFace face;
    face.human = human.id;
    face.face_id = *face_id;
    face.distance_m = camera.distance_to(position);
    face.X_map_face =
        perturb_pose(config_.face_errors.pose, {position, head}, face.distance_m, rng_);
    // The gaze keeps its offset from the (noisy) head direction.
    face.gaze_rad = core::wrap_angle(face.X_map_face.theta +
                                     core::angle_difference(human.gaze.direction_rad, head));
    face.gaze_target = human.gaze.target;
    face.pitch_rad = human.head_pitch_rad;
    face.posture = human.posture.apparent();
    analyse(human, face);
    face.roi = pinhole_region(camera, camera_config.z_m, face.X_map_face.position,
                              config_.human_model.eye_height(face.posture) - kFaceCentreBelowEyes_m,
                              kFaceWidth_m, kFaceHeight_m);
    faces.push_back(std::move(face));
  }
}

}  // namespace ari_social_sim::perception
