#include "world_markers.hpp"

#include <cmath>
#include <cstdio>

#include "ari_social_sim/core/angles.hpp"
#include "marker_builder.hpp"

namespace ari_social_sim::nodes {
namespace {

using visualization_msgs::Marker;

std::string utterance(const world::SpeechSnapshot& speech) {
  // The word being played is marked, so a viewer sees the speech advance word by word.
  return speech.act + ": " + speech.content + "  [" + speech.current_word + "]";
}

void add_static(MarkerBuilder& b, const model::WorldDescription& world) {
  const std_msgs::ColorRGBA wall = rgba(0.25f, 0.45f, 0.25f);
  const std_msgs::ColorRGBA furniture = rgba(0.35f, 0.75f, 0.35f);
  int id = 0;
  for (const model::StaticObject& object : world.objects) {
    const bool is_wall = object.type == model::ShapeType::kWall;
    const double height = is_wall ? 1.0 : 0.5;
    switch (object.type) {
      case model::ShapeType::kWall:
      case model::ShapeType::kBox: {
        Marker& m = b.add("static", id++, Marker::CUBE, is_wall ? wall : furniture);
        m.pose.position = point(object.pose.position.x(), object.pose.position.y(), 0.5 * height);
        m.pose.orientation = yaw_quaternion(object.pose.theta);
        m.scale.x = object.size.x();
        m.scale.y = object.size.y();
        m.scale.z = height;
        break;
      }
      case model::ShapeType::kCircle: {
        Marker& m = b.add("static", id++, Marker::CYLINDER, furniture);
        m.pose.position = point(object.pose.position.x(), object.pose.position.y(), 0.5 * height);
        m.scale.x = m.scale.y = 2.0 * object.radius_m;
        m.scale.z = height;
        break;
      }
      case model::ShapeType::kPolygon: {
        // A prism drawn as a triangle fan on top of the outline.
        Marker& m = b.add("static", id++, Marker::TRIANGLE_LIST, furniture);
        for (size_t i = 1; i + 1 < object.points.size(); ++i) {
          for (size_t k : {size_t{0}, i, i + 1}) {
            m.points.push_back(point(object.points[k].x(), object.points[k].y(), height));
          }
        }
        break;
      }
    }
  }
}

}  // namespace

visualization_msgs::MarkerArray world_markers(const world::WorldSnapshot& snapshot,
                                              const model::WorldDescription& world,
                                              const std::string& frame_id) {
  visualization_msgs::MarkerArray array;
  MarkerBuilder b(frame_id, array);
  b.delete_all();
  add_static(b, world);

  // Colours: static geometry green as in D6.4's GUI, agents red, ARI white, gaze yellow.
  const std_msgs::ColorRGBA body = rgba(0.85f, 0.2f, 0.2f);
  const std_msgs::ColorRGBA heading = rgba(0.5f, 0.05f, 0.05f);
  const std_msgs::ColorRGBA gaze = rgba(1.0f, 0.85f, 0.1f);
  const std_msgs::ColorRGBA label = rgba(1.0f, 1.0f, 1.0f);
  const std_msgs::ColorRGBA speech = rgba(0.55f, 0.85f, 1.0f);
  for (const world::HumanSnapshot& h : snapshot.humans) {
    const int id = static_cast<int>(h.id);
    const double x = h.pose.position.x(), y = h.pose.position.y();
    Marker& cylinder = b.add("humans/body", id, Marker::CYLINDER, body);
    cylinder.pose.position = point(x, y, 0.85);
    cylinder.scale.x = cylinder.scale.y = 0.4;
    cylinder.scale.z = 1.7;
    b.arrow("humans/heading", id, x, y, 1.0, h.pose.theta, 0.5, heading);
    b.arrow("humans/gaze", id, x, y, 1.65, h.gaze.direction_rad, 0.7, gaze);
    char text[160];
    std::snprintf(text, sizeof text, "%u %s\n%.0f y, %s, %s%s", h.id, h.name.c_str(), h.age_years,
                  model::to_string(h.gender), model::to_string(h.emotion), h.mask ? ", mask" : "");
    b.text("humans/label", id, x, y, 2.1, text, 0.16, label);
    if (h.speech.is_speaking) {
      b.text("humans/speech", id, x, y, 2.5, utterance(h.speech), 0.18, speech);
    }
  }
  if (snapshot.ari) {
    const world::AriSnapshot& ari = *snapshot.ari;
    const core::Pose2& pose = ari.pose;
    // Footprint x -0.60..0.16 m in base_footprint: its centre is 0.22 m behind the wheel axle.
    const Eigen::Vector2d centre = pose.transform({-0.22, 0.0});
    Marker& base = b.add("ari/base", 0, Marker::CUBE, rgba(0.95f, 0.95f, 0.95f));
    base.pose.position = point(centre.x(), centre.y(), 0.6);
    base.pose.orientation = yaw_quaternion(pose.theta);
    base.scale.x = 0.76;
    base.scale.y = 0.54;
    base.scale.z = 1.2;
    const Eigen::Vector2d head = pose.transform({-0.2255, 0.0});
    b.arrow("ari/head", 0, head.x(), head.y(), 1.45, pose.theta + ari.head_pan_rad, 0.8,
            rgba(0.2f, 0.4f, 1.0f));
    b.text("ari/label", 0, head.x(), head.y(), 1.8, "ARI " + std::to_string(ari.id), 0.18, label);
    if (ari.speech.is_speaking) {
      b.text("ari/speech", 0, head.x(), head.y(), 2.2, utterance(ari.speech), 0.18, speech);
    }
  }
  for (const world::GroupSnapshot& g : snapshot.groups) {
    b.circle("groups/ospace", static_cast<int>(g.id), g.centre.x(), g.centre.y(), 0.02,
             g.ospace_radius_m, 0.03, rgba(1.0f, 0.6f, 0.0f, 0.9f));
    b.text("groups/label", static_cast<int>(g.id), g.centre.x(), g.centre.y(), 0.3,
           "group " + std::to_string(g.id) + " (" + model::to_string(g.arrangement) +
               (g.robot_joining != model::kNoObject ? ", ARI joining)" : ")"),
           0.15, rgba(1.0f, 0.6f, 0.0f));
  }
  // Walking groups: the leader's walking direction, the goal and what the group is doing.
  for (const world::WalkingGroupSnapshot& w : snapshot.walking_groups) {
    const int id = static_cast<int>(w.id);
    const std_msgs::ColorRGBA colour = rgba(0.2f, 0.8f, 0.4f);
    b.arrow("walking_groups/heading", id, w.leader.x(), w.leader.y(), 0.05, w.heading_rad, 0.6,
            colour);
    b.circle("walking_groups/goal", id, w.goal.position.x(), w.goal.position.y(), 0.02, 0.5, 0.03,
             colour);
    const char* doing = w.arrived ? ", arrived" : w.waiting ? ", waiting" : "";
    b.text("walking_groups/label", id, w.leader.x(), w.leader.y(), 2.1,
           "walking group " + std::to_string(w.id) + " (" + world::to_string(w.formation) + doing +
               ")",
           0.15, colour);
  }
  return array;
}

}  // namespace ari_social_sim::nodes
