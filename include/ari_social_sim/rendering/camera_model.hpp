#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ari_social_sim::rendering {

// Pixel convention shared by every model here and by sensor_msgs/CameraInfo: pixel (u, v) has its
// centre at integer coordinates, u grows right and v down, so a W-pixel-wide image spans
// u in [-0.5, W - 0.5]. Points are given in the camera's optical frame (REP-103: z forward, x
// right, y down), in metres.

/// Ideal pinhole camera (no distortion): u = fx x / z + cx, v = fy y / z + cy.
struct PinholeModel {
  int width{0};   // pixels
  int height{0};  // pixels
  double fx{0.0};
  double fy{0.0};
  double cx{0.0};
  double cy{0.0};

  /// Square pixels and the principal point at the image centre, with the horizontal field of view
  /// spanning the full image width: fx = (width / 2) / tan(hfov / 2), cx = (width - 1) / 2.
  static PinholeModel from_horizontal_fov(int width, int height, double hfov_rad);

  /// Pixel of a point, or nothing when the point is not in front of the camera (z <= 0). The pixel
  /// may lie outside the image; callers check with contains().
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& point_optical) const;
  /// Direction through a pixel, scaled so that z = 1.
  Eigen::Vector3d ray(double u, double v) const;
  bool contains(const Eigen::Vector2d& pixel) const;
  double vertical_fov_rad() const;
};

/// Equidistant ("f-theta") fisheye: a ray at angle theta from the optical axis lands at distance
/// r = f theta from the principal point, in the direction of its azimuth. Rays beyond
/// max_theta_rad are outside the lens and render black.
struct FisheyeModel {
  int width{0};
  int height{0};
  double f{0.0};  // pixels per radian
  double cx{0.0};
  double cy{0.0};
  double max_theta_rad{0.0};

  /// The horizontal field of view spans the full width: f = width / hfov, max_theta = hfov / 2.
  static FisheyeModel from_horizontal_fov(int width, int height, double hfov_rad);

  /// Pixel of a point, or nothing when its ray is beyond max_theta_rad.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& point_optical) const;
  /// Unit ray through a pixel, or nothing when the pixel is outside the lens circle.
  std::optional<Eigen::Vector3d> unproject(double u, double v) const;
};

/// The intrinsic part of sensor_msgs/CameraInfo (frame and stamp are the node's), row-major.
struct CameraInfo {
  int width{0};
  int height{0};
  std::string distortion_model;  // "plumb_bob" or "equidistant" (image_geometry's names)
  std::vector<double> D;
  std::array<double, 9> K{};
  std::array<double, 9> R{};
  std::array<double, 12> P{};
};

/// plumb_bob with five zero coefficients; R identity; P = [K | 0] (a monocular camera).
CameraInfo camera_info_of(const PinholeModel& model);
/// equidistant with four zero coefficients (OpenCV's fisheye model reduces to r = f theta); K holds
/// f and the principal point, R identity, P = [K | 0].
CameraInfo camera_info_of(const FisheyeModel& model);

}  // namespace ari_social_sim::rendering
