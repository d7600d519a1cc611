#include "world_markers.hpp"

#include <cmath>
#include <cstdio>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::nodes {
namespace {

using visualization_msgs::Marker;

// Colours: static geometry green as in the seed's GUI, agents red, ARI white, gaze yellow.
std_msgs::ColorRGBA rgba(float r, float g, float b, float a = 1.0f) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

geometry_msgs::Point point(double x, double y, double z = 0.0) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

geometry_msgs::Quaternion yaw(double theta) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * theta);
  q.w = std::cos(0.5 * theta);
  return q;
}

class MarkerBuilder {
 public:
  MarkerBuilder(const std::string& frame_id, visualization_msgs::MarkerArray& out)
      : frame_id_(frame_id), out_(out) {}

  Marker& add(const std::string& ns, int id, int type, const std_msgs::ColorRGBA& colour) {
    Marker m;
    m.header.frame_id = frame_id_;
    m.ns = ns;
    m.id = id;
    m.type = type;
    m.action = Marker::ADD;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    m.color = colour;
    out_.markers.push_back(std::move(m));
    return out_.markers.back();
  }

  void arrow(const std::string& ns, int id, double x, double y, double z, double theta,
             double length, const std_msgs::ColorRGBA& colour) {
    Marker& m = add(ns, id, Marker::ARROW, colour);
    m.points = {point(x, y, z),
                point(x + length * std::cos(theta), y + length * std::sin(theta), z)};
    m.scale.x = 0.04;
    m.scale.y = 0.08;
    m.scale.z = 0.1;
  }

  void text(const std::string& ns, int id, double x, double y, double z, const std::string& words,
            double height, const std_msgs::ColorRGBA& colour) {
    Marker& m = add(ns, id, Marker::TEXT_VIEW_FACING, colour);
    m.pose.position = point(x, y, z);
    m.scale.z = height;
    m.text = words;
  }

 private:
  const std::string& frame_id_;
  visualization_msgs::MarkerArray& out_;
};

std::string utterance(const world::SpeechSnapshot& speech) {
  // The word being played is marked, so a viewer sees the speech advance word by word.
  return speech.act + ": " + speech.content + "  [" + speech.current_word + "]";
}

void add_static(MarkerBuilder& b, const world::WorldDescription& world) {
  const std_msgs::ColorRGBA wall = rgba(0.25f, 0.45f, 0.25f);
  const std_msgs::ColorRGBA furniture = rgba(0.35f, 0.75f, 0.35f);
  int id = 0;
  for (const world::StaticObject& object : world.objects) {
    const bool is_wall = object.type == world::ShapeType::kWall;
    const double height = is_wall ? 1.0 : 0.5;
    switch (object.type) {
      case world::ShapeType::kWall:
      case world::ShapeType::kBox: {
        Marker& m = b.add("static", id++, Marker::CUBE, is_wall ? wall : furniture);
        m.pose.position = point(object.pose.position.x(), object.pose.position.y(), 0.5 * height);
        m.pose.orientation = yaw(object.pose.theta);
        m.scale.x = object.size.x();
        m.scale.y = object.size.y();
        m.scale.z = height;
        break;
      }
      case world::ShapeType::kCircle: {
        Marker& m = b.add("static", id++, Marker::CYLINDER, furniture);
        m.pose.position = point(object.pose.position.x(), object.pose.position.y(), 0.5 * height);
        m.scale.x = m.scale.y = 2.0 * object.radius_m;
        m.scale.z = height;
        break;
      }
      case world::ShapeType::kPolygon: {
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
                                              const world::WorldDescription& world,
                                              const std::string& frame_id) {
  visualization_msgs::MarkerArray array;
  MarkerBuilder b(frame_id, array);
  b.add("", 0, Marker::CUBE, rgba(0, 0, 0)).action = Marker::DELETEALL;
  add_static(b, world);

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
                  world::to_string(h.gender), world::to_string(h.emotion), h.mask ? ", mask" : "");
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
    base.pose.orientation = yaw(pose.theta);
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
    Marker& circle = b.add("groups/ospace", static_cast<int>(g.id), Marker::LINE_STRIP,
                           rgba(1.0f, 0.6f, 0.0f, 0.9f));
    circle.scale.x = 0.03;
    constexpr int kSegments = 48;
    for (int i = 0; i <= kSegments; ++i) {
      const double a = 2.0 * core::kPi * i / kSegments;
      circle.points.push_back(point(g.centre.x() + g.ospace_radius_m * std::cos(a),
                                    g.centre.y() + g.ospace_radius_m * std::sin(a), 0.02));
    }
    b.text("groups/label", static_cast<int>(g.id), g.centre.x(), g.centre.y(), 0.3,
           "group " + std::to_string(g.id), 0.15, rgba(1.0f, 0.6f, 0.0f));
  }
  return array;
}

}  // namespace ari_social_sim::nodes
