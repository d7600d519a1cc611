#include "ari_social_sim/rendering/fisheye_renderer.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::rendering {
namespace {

// Each face's optical z axis (its viewing direction) and x axis, in the fisheye's optical frame.
const std::array<std::pair<Eigen::Vector3d, Eigen::Vector3d>, 6> kFaceAxes{{
    {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()},
    {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitZ()},
    {-Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()},
    {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX()},
    {-Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX()},
    {-Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitX()},
}};

}  // namespace

Eigen::Matrix3d FisheyeRenderer::R_optical_face(int face) {
  const auto& [z, x] = kFaceAxes[face];
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = z.cross(x);
  R.col(2) = z;
  return R;
}

FisheyeRenderer::FisheyeRenderer(const FisheyeModel& model, int face_size_px) : model_(model) {
  const int size = face_size_px > 0 ? face_size_px : 2 * static_cast<int>(std::ceil(model.f));
  // A 90 degree pinhole: f = size / 2.
  face_ = PinholeModel::from_horizontal_fov(size, size, M_PI / 2);

  std::array<Eigen::Matrix3d, 6> R_face_optical;
  for (int face = 0; face < 6; ++face) {
    R_face_optical[face] = R_optical_face(face).transpose();
  }
  samples_.resize(static_cast<size_t>(model.width) * model.height);
  for (int v = 0; v < model.height; ++v) {
    for (int u = 0; u < model.width; ++u) {
      const auto ray = model.unproject(u, v);
      if (!ray) {
        continue;
      }
      // The face the ray leaves the cube through is the one its largest component points at.
      int best = 0;
      double best_dot = -2.0;
      for (int face = 0; face < 6; ++face) {
        const double dot = kFaceAxes[face].first.dot(*ray);
        if (dot > best_dot) {
          best_dot = dot;
          best = face;
        }
      }
      const auto pixel = face_.project(R_face_optical[best] * *ray);
      Sample& sample = samples_[static_cast<size_t>(v) * model.width + u];
      sample.face = static_cast<int8_t>(best);
      sample.u = static_cast<float>(std::clamp(pixel->x(), 0.0, face_.width - 1.0));
      sample.v = static_cast<float>(std::clamp(pixel->y(), 0.0, face_.height - 1.0));
      face_used_[best] = true;
    }
  }
}

int FisheyeRenderer::faces_drawn() const {
  return static_cast<int>(std::count(face_used_.begin(), face_used_.end(), true));
}

void FisheyeRenderer::render(Renderer& renderer, const Eigen::Isometry3d& X_world_optical,
                             cv::Mat& colour, int samples) {
  ViewOptions options;
  options.samples = samples;
  for (int face = 0; face < 6; ++face) {
    if (face_used_[face]) {
      Eigen::Isometry3d X_world_face = X_world_optical;
      X_world_face.linear() = X_world_optical.linear() * R_optical_face(face);
      renderer.render(face_, X_world_face, options, face_images_[face]);
    }
  }
  colour.create(model_.height, model_.width, CV_8UC3);
  const int last = face_.width - 1;
  uint8_t* out = colour.ptr<uint8_t>();
  for (const Sample& sample : samples_) {
    if (sample.face < 0) {
      out[0] = out[1] = out[2] = 0;
      out += 3;
      continue;
    }
    // Bilinear interpolation between the four face pixels around the sample.
    const cv::Mat& image = face_images_[sample.face].colour;
    const int u0 = std::min(static_cast<int>(sample.u), last - 1);
    const int v0 = std::min(static_cast<int>(sample.v), last - 1);
    const float a = sample.u - u0, b = sample.v - v0;
    const uint8_t* p00 = image.ptr<uint8_t>(v0) + 3 * u0;
    const uint8_t* p10 = image.ptr<uint8_t>(v0 + 1) + 3 * u0;
    for (int c = 0; c < 3; ++c) {
      const float top = (1 - a) * p00[c] + a * p00[c + 3];
      const float bottom = (1 - a) * p10[c] + a * p10[c + 3];
      // A colour in [0, 255], where + 0.5 rounds right; std::lround would cost a call per
      // channel of every pixel.
      // NOLINTNEXTLINE(bugprone-incorrect-roundings)
      out[c] = static_cast<uint8_t>((1 - b) * top + b * bottom + 0.5f);
    }
    out += 3;
  }
}

}  // namespace ari_social_sim::rendering
