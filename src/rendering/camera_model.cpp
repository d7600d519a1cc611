#include "ari_social_sim/rendering/camera_model.hpp"

#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::rendering {
namespace {

// An undistorted camera's info: zero distortion coefficients of the named model, R identity and
// P = [K | 0].
CameraInfo ideal_info(int width, int height, double fx, double fy, double cx, double cy,
                      const char* distortion_model, size_t coefficient_count) {
  CameraInfo info;
  info.width = width;
  info.height = height;
  info.distortion_model = distortion_model;
  info.D.assign(coefficient_count, 0.0);
  info.K = {fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {fx, 0.0, cx, 0.0, 0.0, fy, cy, 0.0, 0.0, 0.0, 1.0, 0.0};
  return info;
}

}  // namespace

PinholeModel PinholeModel::from_horizontal_fov(int width, int height, double hfov_rad) {
  ARI_CHECK(width > 0 && height > 0 && hfov_rad > 0.0 && hfov_rad < M_PI);
  PinholeModel model;
  model.width = width;
  model.height = height;
  model.fx = 0.5 * width / std::tan(0.5 * hfov_rad);
  model.fy = model.fx;
  model.cx = 0.5 * (width - 1);
  model.cy = 0.5 * (height - 1);
  return model;
}

std::optional<Eigen::Vector2d> PinholeModel::project(const Eigen::Vector3d& point_optical) const {
  if (point_optical.z() <= 0.0) {
    return std::nullopt;
  }
  return Eigen::Vector2d(fx * point_optical.x() / point_optical.z() + cx,
                         fy * point_optical.y() / point_optical.z() + cy);
}

Eigen::Vector3d PinholeModel::ray(double u, double v) const {
  return {(u - cx) / fx, (v - cy) / fy, 1.0};
}

bool PinholeModel::contains(const Eigen::Vector2d& pixel) const {
  return pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() < width - 0.5 &&
         pixel.y() < height - 0.5;
}

double PinholeModel::vertical_fov_rad() const {
  return 2.0 * std::atan(0.5 * height / fy);
}

FisheyeModel FisheyeModel::from_horizontal_fov(int width, int height, double hfov_rad) {
  ARI_CHECK(width > 0 && height > 0 && hfov_rad > 0.0 && hfov_rad <= 2.0 * M_PI);
  FisheyeModel model;
  model.width = width;
  model.height = height;
  model.f = width / hfov_rad;
  model.cx = 0.5 * (width - 1);
  model.cy = 0.5 * (height - 1);
  model.max_theta_rad = 0.5 * hfov_rad;
  return model;
}

std::optional<Eigen::Vector2d> FisheyeModel::project(const Eigen::Vector3d& point_optical) const {
  const double lateral = std::hypot(point_optical.x(), point_optical.y());
  const double theta = std::atan2(lateral, point_optical.z());
  if (theta > max_theta_rad) {
    return std::nullopt;
  }
  if (lateral < 1e-12) {
    return Eigen::Vector2d(cx, cy);
  }
  const double r = f * theta;
  return Eigen::Vector2d(cx + r * point_optical.x() / lateral,
                         cy + r * point_optical.y() / lateral);
}

std::optional<Eigen::Vector3d> FisheyeModel::unproject(double u, double v) const {
  const double du = u - cx;
  const double dv = v - cy;
  const double r = std::hypot(du, dv);
  const double theta = r / f;
  if (theta > max_theta_rad) {
    return std::nullopt;
  }
  if (r < 1e-12) {
    return Eigen::Vector3d::UnitZ();
  }
  const double s = std::sin(theta) / r;
  return Eigen::Vector3d(du * s, dv * s, std::cos(theta));
}

CameraInfo camera_info_of(const PinholeModel& model) {
  return ideal_info(model.width, model.height, model.fx, model.fy, model.cx, model.cy, "plumb_bob",
                    5);
}

CameraInfo camera_info_of(const FisheyeModel& model) {
  return ideal_info(model.width, model.height, model.f, model.f, model.cx, model.cy, "equidistant",
                    4);
}

}  // namespace ari_social_sim::rendering
