#include "marker_builder.hpp"

#include <cmath>

namespace ari_social_sim::nodes {

using visualization_msgs::Marker;

std_msgs::ColorRGBA rgba(float r, float g, float b, float a) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

geometry_msgs::Point point(double x, double y, double z) {
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

geometry_msgs::Quaternion yaw_quaternion(double theta) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * theta);
  q.w = std::cos(0.5 * theta);
  return q;
}

Marker& MarkerBuilder::add(const std::string& ns, int id, int type,
                           const std_msgs::ColorRGBA& colour) {
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

void MarkerBuilder::delete_all() {
  add("", 0, Marker::CUBE, rgba(0, 0, 0)).action = Marker::DELETEALL;
}

void MarkerBuilder::arrow(const std::string& ns, int id, double x, double y, double z, double theta,
                          double length, const std_msgs::ColorRGBA& colour) {
  Marker& m = add(ns, id, Marker::ARROW, colour);
  m.points = {point(x, y, z), point(x + length * std::cos(theta), y + length * std::sin(theta), z)};
  m.scale.x = 0.04;
  m.scale.y = 0.08;
  m.scale.z = 0.1;
}

void MarkerBuilder::text(const std::string& ns, int id, double x, double y, double z,
                         const std::string& words, double height,
                         const std_msgs::ColorRGBA& colour) {
  Marker& m = add(ns, id, Marker::TEXT_VIEW_FACING, colour);
  m.pose.position = point(x, y, z);
  m.scale.z = height;
  m.text = words;
}

void MarkerBuilder::circle(const std::string& ns, int id, double x, double y, double z,
                           double radius, double width, const std_msgs::ColorRGBA& colour) {
  Marker& m = add(ns, id, Marker::LINE_STRIP, colour);
  m.scale.x = width;
  constexpr int kSegments = 48;
  for (int i = 0; i <= kSegments; ++i) {
    const double a = 2.0 * M_PI * i / kSegments;
    m.points.push_back(point(x + radius * std::cos(a), y + radius * std::sin(a), z));
  }
}

}  // namespace ari_social_sim::nodes
