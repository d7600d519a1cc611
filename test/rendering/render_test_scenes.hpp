#pragma once

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>

#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering::test {

/// A camera pose whose optical axis looks along world +x from `position`, image x to the right
/// (world -y) and image y down (world -z): the optical frame of a level camera facing +x.
inline Eigen::Isometry3d level_camera_facing_x(const Eigen::Vector3d& position) {
  Eigen::Matrix3d R_world_optical;
  R_world_optical.col(0) = -Eigen::Vector3d::UnitY();
  R_world_optical.col(1) = -Eigen::Vector3d::UnitZ();
  R_world_optical.col(2) = Eigen::Vector3d::UnitX();
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = R_world_optical;
  X.translation() = position;
  return X;
}

/// A box with its centre at `centre`, turned by `yaw` about world z.
inline RenderPrimitive box(const Eigen::Vector3d& centre, const Eigen::Vector3d& size,
                           double yaw = 0.0,
                           const Eigen::Vector3f& colour = Eigen::Vector3f(0.8f, 0.8f, 0.8f)) {
  RenderPrimitive primitive;
  primitive.shape = PrimitiveShape::kBox;
  primitive.X_world_shape =
      Eigen::Translation3d(centre) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
  primitive.size = size;
  primitive.colour = colour;
  return primitive;
}

/// Mean pixel (u, v) of the RGB pixels that pass `selected`, and how many there were.
template <class Predicate>
std::pair<Eigen::Vector2d, int> centroid_of(const cv::Mat& rgb, Predicate selected) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (int v = 0; v < rgb.rows; ++v) {
    for (int u = 0; u < rgb.cols; ++u) {
      if (selected(rgb.at<cv::Vec3b>(v, u))) {
        sum += Eigen::Vector2d(u, v);
        ++count;
      }
    }
  }
  return {count > 0 ? Eigen::Vector2d(sum / count) : sum, count};
}

}  // namespace ari_social_sim::rendering::test
