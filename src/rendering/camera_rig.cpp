#include "ari_social_sim/rendering/camera_rig.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::rendering {

namespace {

// A fisheye's lens is not a pinhole's: its falloff is not the cos^k law, and the lens circle's
// black edge is what a user sees of it. Its sensor has no vignetting.
std::unique_ptr<CameraSensor> sensor_of(const CameraSpec& spec, CameraEffects effects,
                                        uint64_t seed, size_t index) {
  if (spec.kind == CameraKind::kFisheye) {
    effects.corner_illumination = 1.0;
  }
  return std::make_unique<CameraSensor>(effects, spec.width, spec.height, spec.hfov_rad, seed,
                                        index);
}

}  // namespace

CameraRig::CameraRig(const CameraRigConfig& config, uint64_t seed)
    : depth_encoding_(core::validated(config).depth_encoding),
      renderer_(std::make_unique<Renderer>()) {
  if (config.effects.enabled) {
    samples_ = config.effects.antialiasing_samples;
    motion_blur_ = config.effects.motion_blur;
  }
  for (const CameraSpec& spec : config.cameras) {
    if (!spec.enabled) {
      continue;
    }
    cameras_.push_back(spec);
    if (spec.kind == CameraKind::kFisheye) {
      const FisheyeModel model =
          FisheyeModel::from_horizontal_fov(spec.width, spec.height, spec.hfov_rad);
      fisheyes_.push_back(std::make_unique<FisheyeRenderer>(model));
      pinholes_.emplace_back();
      infos_.push_back(camera_info_of(model));
    } else {
      const PinholeModel model =
          PinholeModel::from_horizontal_fov(spec.width, spec.height, spec.hfov_rad);
      fisheyes_.push_back(nullptr);
      pinholes_.push_back(model);
      infos_.push_back(camera_info_of(model));
    }
    next_due_s_.push_back(0.0);
    frame_time_s_.push_back(0.0);
    motions_.emplace_back();
    sensors_.push_back(config.effects.enabled
                           ? sensor_of(spec, config.effects, seed, cameras_.size() - 1)
                           : nullptr);
  }
}

void CameraRig::set_world(const model::WorldDescription& world, const SceneStyle& style) {
  renderer_->set_static_primitives(static_primitives_of(world, style));
}

void CameraRig::set_dynamic_mesh(const RenderMesh& mesh) {
  renderer_->set_dynamic_mesh(mesh);
  if (motion_blur_) {
    label_centres_ = label_centres(mesh);
  }
}

std::vector<size_t> CameraRig::due(double time_s) {
  std::vector<size_t> due_now;
  for (size_t i = 0; i < cameras_.size(); ++i) {
    if (time_s + 1e-9 < next_due_s_[i]) {
      continue;
    }
    due_now.push_back(i);
    frame_time_s_[i] = time_s;
    const double period = 1.0 / cameras_[i].rate_hz;
    // The next frame on the k / rate grid strictly after now.
    next_due_s_[i] = (std::floor(time_s * cameras_[i].rate_hz + 1e-6) + 1.0) * period;
  }
  return due_now;
}

void CameraRig::restart(uint64_t seed) {
  std::fill(next_due_s_.begin(), next_due_s_.end(), 0.0);
  std::fill(frame_time_s_.begin(), frame_time_s_.end(), 0.0);
  for (FrameMotion& motion : motions_) {
    motion.restart();
  }
  for (const std::unique_ptr<CameraSensor>& sensor : sensors_) {
    if (sensor) {
      sensor->restart(seed);
    }
  }
}

void CameraRig::expose(size_t i, cv::Mat& colour, const cv::Mat& labels,
                       const ImageMotion& motion) {
  if (sensors_[i]) {
    sensors_[i]->expose(colour, labels, motion);
  }
}

ImageMotion CameraRig::motion_of(size_t i, const Eigen::Isometry3d& X_world_optical) {
  if (!motion_blur_) {
    return {};
  }
  return motions_[i].per_second(frame_time_s_[i], 1.0 / cameras_[i].rate_hz, X_world_optical,
                                pinholes_[i], label_centres_);
}

void CameraRig::render(size_t i, const Eigen::Isometry3d& X_world_optical, CameraFrame& out,
                       bool labels) {
  const CameraSpec& spec = cameras_[i];
  out.labels.release();
  if (spec.kind == CameraKind::kFisheye) {
    fisheyes_[i]->render(*renderer_, X_world_optical, out.colour, samples_);
    expose(i, out.colour, cv::Mat(), ImageMotion());
    out.depth.release();
    return;
  }
  ViewOptions options;
  options.depth = spec.kind == CameraKind::kRgbd;
  options.labels = labels || motion_blur_;  // motion blur finds the people by their labels
  options.samples = samples_;
  renderer_->render(pinholes_[i], X_world_optical, options, scratch_);
  // Swapping hands the rendered buffers over without a copy; the renderer refills the old ones.
  std::swap(out.colour, scratch_.colour);
  expose(i, out.colour, scratch_.labels, motion_of(i, X_world_optical));
  if (labels) {
    std::swap(out.labels, scratch_.labels);
  }
  if (!options.depth) {
    out.depth.release();
    return;
  }
  clip_depth_range(scratch_.depth, spec.min_range_m, spec.max_range_m);
  if (depth_encoding_ == DepthEncoding::kMetres32F) {
    std::swap(out.depth, scratch_.depth);
  } else {
    out.depth = to_millimetres(scratch_.depth);
  }
}

}  // namespace ari_social_sim::rendering
