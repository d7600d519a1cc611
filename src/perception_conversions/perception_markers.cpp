#include "perception_markers.hpp"

#include <cmath>
#include <cstdio>

#include "ari_social_sim/perception/expression.hpp"
#include "world_conversions/marker_builder.hpp"

namespace ari_social_sim::nodes {
namespace {

using visualization_msgs::Marker;

// A translucent flat wedge of a field of view (a full disc when the wedge is 360 degrees).
void add_wedge(MarkerBuilder& b, const std::string& ns, const perception::FieldOfView& fov,
               double z, const std_msgs::ColorRGBA& colour) {
  Marker& m = b.add(ns, 0, Marker::TRIANGLE_LIST, colour);
  const Eigen::Vector2d& apex = fov.X_map_sensor.position;
  constexpr int kSegments = 36;
  for (int i = 0; i < kSegments; ++i) {
    const double a0 =
        fov.X_map_sensor.theta - fov.half_angle_rad + 2.0 * fov.half_angle_rad * i / kSegments;
    const double a1 = a0 + 2.0 * fov.half_angle_rad / kSegments;
    m.points.push_back(point(apex.x(), apex.y(), z));
    m.points.push_back(
        point(apex.x() + fov.range_m * std::cos(a0), apex.y() + fov.range_m * std::sin(a0), z));
    m.points.push_back(
        point(apex.x() + fov.range_m * std::cos(a1), apex.y() + fov.range_m * std::sin(a1), z));
  }
}

const char* gender_text(model::Gender gender) {
  return gender == model::Gender::kNonIdentified ? "undefined" : model::to_string(gender);
}

}  // namespace

visualization_msgs::MarkerArray perception_markers(const perception::PerceptionFrame& frame,
                                                   const perception::PerceptionConfig& config,
                                                   const std::string& frame_id) {
  visualization_msgs::MarkerArray array;
  MarkerBuilder b(frame_id, array);
  b.delete_all();
  if (frame.has_ari) {
    add_wedge(b, "perception/fov/body_camera", frame.sensors.body_camera, 0.01,
              rgba(0.3f, 0.6f, 1.0f, 0.10f));
    add_wedge(b, "perception/fov/face_camera", frame.sensors.face_camera, 0.02,
              rgba(1.0f, 0.9f, 0.2f, 0.25f));
    b.circle("perception/fov/microphone", 0, frame.sensors.microphone.x(),
             frame.sensors.microphone.y(), 0.03, frame.sensors.listening_range_m, 0.03,
             rgba(0.6f, 1.0f, 0.6f, 0.6f));
  }

  const std_msgs::ColorRGBA body = rgba(0.2f, 0.45f, 1.0f, 0.8f);
  // Labels dark enough to read on the light floor of /map.
  const std_msgs::ColorRGBA label = rgba(0.0f, 0.1f, 0.5f);
  int id = 0;
  for (const perception::PerceivedBody& perceived : frame.bodies) {
    const double x = perceived.X_map_body.position.x(), y = perceived.X_map_body.position.y();
    Marker& cylinder = b.add("perception/bodies", id, Marker::CYLINDER, body);
    cylinder.pose.position = point(x, y, 0.8);
    cylinder.scale.x = cylinder.scale.y = 2.0 * config.occlusion.person_radius_m;
    cylinder.scale.z = 1.6;
    b.arrow("perception/bodies/heading", id, x, y, 1.05, perceived.X_map_body.theta, 0.5,
            rgba(0.05f, 0.15f, 0.6f));
    b.text("perception/bodies/label", id, x, y, 1.95,
           perceived.body_id + " / " + perceived.person_id, 0.2, label);
    ++id;
  }
  id = 0;
  for (const perception::PerceivedFace& face : frame.faces) {
    const double x = face.X_map_face.position.x(), y = face.X_map_face.position.y();
    const double z = config.human_model.eye_height_m;
    Marker& head = b.add("perception/faces", id, Marker::SPHERE, rgba(1.0f, 0.85f, 0.3f));
    head.pose.position = point(x, y, z);
    head.scale.x = head.scale.y = head.scale.z = 0.22;
    b.arrow("perception/faces/gaze", id, x, y, z, face.gaze_rad, 0.8, rgba(1.0f, 0.6f, 0.0f));
    char text[160];
    std::snprintf(text, sizeof text, "face %s: %.0f y, %s, %s%s", face.face_id.c_str(),
                  face.age_years, gender_text(face.gender),
                  perception::expression_of(face.emotion).name, face.mask ? ", mask" : "");
    b.text("perception/faces/label", id, x, y, 2.2, text, 0.2, rgba(0.6f, 0.25f, 0.0f));
    ++id;
  }
  id = 0;
  for (const perception::PerceivedVoice& voice : frame.voices) {
    if (voice.transcript.empty()) {
      continue;
    }
    const std::string words =
        voice.is_speaking ? voice.transcript + " ..." : "\"" + voice.transcript + "\"";
    b.text("perception/speech", id++, voice.position.x(), voice.position.y(), 2.5,
           "voice " + voice.voice_id + ": " + words, 0.2, rgba(0.0f, 0.4f, 0.0f));
  }
  id = 0;
  for (const perception::PersonReport& person : frame.persons) {
    if (person.tracked || person.location_confidence <= 0.0) {
      continue;
    }
    const float fade = static_cast<float>(person.location_confidence);
    Marker& ghost =
        b.add("perception/persons/lost", id, Marker::SPHERE, rgba(0.7f, 0.7f, 0.7f, 0.6f * fade));
    ghost.pose.position = point(person.location.x(), person.location.y(), 1.6);
    ghost.scale.x = ghost.scale.y = ghost.scale.z = 0.25;
    char text[96];
    std::snprintf(text, sizeof text, "%s (%.0f %%)", person.person_id.c_str(), 100.0 * fade);
    b.text("perception/persons/lost/label", id, person.location.x(), person.location.y(), 1.9, text,
           0.13, rgba(0.8f, 0.8f, 0.8f, fade));
    ++id;
  }
  return array;
}

}  // namespace ari_social_sim::nodes
