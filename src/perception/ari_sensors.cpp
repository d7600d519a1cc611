#include "ari_social_sim/perception/ari_sensors.hpp"

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::perception {

AriSensors AriSensors::of(const world::AriSnapshot& ari, const PerceptionConfig& config) {
  const core::Pose2& X_map_base = ari.pose;
  AriSensors sensors;

  const BodyCameraConfig& body = config.body_camera;
  sensors.body_camera.X_map_sensor = {X_map_base.transform({body.x_m, body.y_m}), X_map_base.theta};
  sensors.body_camera.half_angle_rad = 0.5 * core::deg_to_rad(body.field_of_view_deg);
  sensors.body_camera.range_m = body.range_m;

  // X_map_camera = X_map_base * X_base_pan(pan) * X_pan_camera.
  const FaceCameraConfig& face = config.face_camera;
  const core::Pose2 X_map_pan{X_map_base.transform({face.pan_axis_x_m, face.pan_axis_y_m}),
                              core::wrap_angle(X_map_base.theta + ari.head_pan_rad)};
  sensors.face_camera.X_map_sensor = {X_map_pan.transform({face.x_m, face.y_m}), X_map_pan.theta};
  sensors.face_camera.half_angle_rad = 0.5 * core::deg_to_rad(face.field_of_view_deg);
  sensors.face_camera.range_m = face.range_m;

  sensors.microphone = X_map_base.transform({config.microphone.x_m, config.microphone.y_m});
  sensors.listening_range_m = config.microphone.max_distance_m;
  return sensors;
}

}  // namespace ari_social_sim::perception
