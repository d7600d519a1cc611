#pragma once

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Quaternion.h>
#include <std_msgs/ColorRGBA.h>
#include <visualization_msgs/MarkerArray.h>

#include <string>

namespace ari_social_sim::nodes {

std_msgs::ColorRGBA rgba(float r, float g, float b, float a = 1.0f);
geometry_msgs::Point point(double x, double y, double z = 0.0);
/// A rotation about z by `theta` (rad).
geometry_msgs::Quaternion yaw_quaternion(double theta);

/// Appends markers of one frame to a MarkerArray: every marker in `frame_id`, unit scale,
/// identity orientation, action ADD unless changed.
class MarkerBuilder {
 public:
  MarkerBuilder(const std::string& frame_id, visualization_msgs::MarkerArray& out)
      : frame_id_(frame_id), out_(out) {}

  visualization_msgs::Marker& add(const std::string& ns, int id, int type,
                                  const std_msgs::ColorRGBA& colour);
  /// A DELETEALL first, so that entities gone since the last array disappear.
  void delete_all();
  /// A flat arrow from (x, y, z) along `theta`.
  void arrow(const std::string& ns, int id, double x, double y, double z, double theta,
             double length, const std_msgs::ColorRGBA& colour);
  void text(const std::string& ns, int id, double x, double y, double z, const std::string& words,
            double height, const std_msgs::ColorRGBA& colour);
  /// A horizontal circle outline at height z.
  void circle(const std::string& ns, int id, double x, double y, double z, double radius,
              double width, const std_msgs::ColorRGBA& colour);

 private:
  const std::string& frame_id_;
  visualization_msgs::MarkerArray& out_;
};

}  // namespace ari_social_sim::nodes
