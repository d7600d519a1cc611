#include "ari_social_sim/perception/body_tracker.hpp"

#include "ari_social_sim/perception/image_regions.hpp"
#include "ari_social_sim/perception/pose_noise.hpp"

namespace ari_social_sim::perception {
namespace {

// A body's box in the image reaches from the floor to a little above the eyes.
constexpr double kHeadTopAboveEyes_m = 0.12;

}  // namespace

BodyTracker::BodyTracker(const PerceptionConfig& config, TransientIds& ids, core::Rng rng)
    : config_(config),
      track_ids_(config.body_errors.detection, ids, core::Rng(rng.next_u64())),
      rng_(rng) {}

void BodyTracker::update(const world::WorldSnapshot& snapshot, const AriSensors& sensors,
                         const SightObstacles& obstacles, double dt_s,
                         std::vector<PerceivedBody>& bodies) {
  const FieldOfView& camera = sensors.body_camera;
  const BodyCameraConfig& camera_config = config_.body_camera;
  for (size_t i = 0; i < snapshot.humans.size(); ++i) {
    const world::HumanSnapshot& human = snapshot.humans[i];
    const bool in_view = camera.contains(human.pose.position);
    const double visible =
        in_view ? visible_fraction(camera, obstacles, i, config_.occlusion.rays_per_person) : 0.0;
    const Sighting sighting =
        decide_sighting(config_.body_errors.detection, camera, human.pose.position, visible,
                        camera_config.min_visible_fraction, rng_);
    const std::string* body_id = track_ids_.update(human.id, sighting, dt_s);
    if (body_id == nullptr) {
      continue;
    }
    PerceivedBody body;
    body.human = human.id;
    body.body_id = *body_id;
    body.distance_m = camera.distance_to(human.pose.position);
    body.X_map_body = perturb_pose(config_.body_errors.pose, human.pose, body.distance_m, rng_);
    body.visible_fraction = visible;
    body.posture = human.posture.apparent();
    body.roi = fisheye_region(camera, camera_config.z_m, body.X_map_body.position,
                              config_.occlusion.person_radius_m,
                              config_.human_model.eye_height(body.posture) + kHeadTopAboveEyes_m);
    bodies.push_back(std::move(body));
  }
}

}  // namespace ari_social_sim::perception
