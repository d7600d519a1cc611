#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/renderer.hpp"

namespace ari_social_sim::rendering {

/// Renders an equidistant fisheye image from pinhole views: the faces of a cube around the optical
/// centre (90 degree pinholes) are drawn with the Renderer and resampled bilinearly through a
/// lookup table computed once from the lens model. Only the faces the lens sees are drawn (five
/// for a 180 degree lens). Pixels beyond the lens' max_theta are black.
class FisheyeRenderer {
 public:
  /// face_size_px 0 picks faces whose centre resolution matches the fisheye's (2 f pixels).
  explicit FisheyeRenderer(const FisheyeModel& model, int face_size_px = 0);

  const FisheyeModel& model() const { return model_; }
  int face_size_px() const { return face_.width; }
  /// How many of the six cube faces are drawn per image.
  int faces_drawn() const;

  /// Colour image (CV_8UC3, RGB) seen from an optical frame in the world.
  void render(Renderer& renderer, const Eigen::Isometry3d& X_world_optical, cv::Mat& colour,
              int samples = 1);

  /// Rotation from a face's optical frame to the fisheye's (faces 0..5: +z, +x, -x, +y, -y, -z).
  static Eigen::Matrix3d R_optical_face(int face);

 private:
  struct Sample {
    int8_t face{-1};  // -1: outside the lens
    float u{0.0f};    // pixel in the face image, clamped inside it
    float v{0.0f};
  };

  FisheyeModel model_;
  PinholeModel face_;
  std::vector<Sample> samples_;  // one per fisheye pixel, row-major
  std::array<bool, 6> face_used_{};
  std::array<RenderedImage, 6> face_images_;
};

}  // namespace ari_social_sim::rendering
