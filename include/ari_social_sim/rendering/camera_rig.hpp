#pragma once

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/camera_rig_config.hpp"
#include "ari_social_sim/rendering/camera_sensor.hpp"
#include "ari_social_sim/rendering/fisheye_renderer.hpp"
#include "ari_social_sim/rendering/frame_motion.hpp"
#include "ari_social_sim/rendering/renderer.hpp"
#include "ari_social_sim/rendering/world_scene.hpp"

namespace ari_social_sim::rendering {

/// One camera's output for one instant.
struct CameraFrame {
  cv::Mat colour;  // CV_8UC3, RGB
  cv::Mat depth;   // RGB-D cameras only: CV_32FC1 metres (NaN invalid) or CV_16UC1 millimetres
                   // (0 invalid), per the rig's depth encoding; aligned pixel for pixel to colour
  cv::Mat labels;  // when asked for (pinhole cameras): CV_16UC1, PeopleFigures' labels per pixel
};

/// ARI's enabled cameras around one renderer: the component a node (or a batch tool) calls with
/// each camera's optical-frame pose in the world. It owns the static scene (set once from the
/// world) and takes the moving part (people, the robot's own body) each tick.
class CameraRig {
 public:
  /// Opens the renderer; throws core::ConfigError for an invalid config
  /// (CameraRigConfig::validate), RenderError when no headless OpenGL context can be made.
  /// `seed` seeds the cameras' sensor noise (core::rng_streams::kCameraSensor).
  explicit CameraRig(const CameraRigConfig& config, uint64_t seed = 1);

  /// The enabled cameras, in the order of ari_camera_specs().
  const std::vector<CameraSpec>& cameras() const { return cameras_; }
  /// camera_info of camera i (the depth image of an RGB-D camera shares its colour intrinsics).
  const CameraInfo& info(size_t i) const { return infos_[i]; }
  DepthEncoding depth_encoding() const { return depth_encoding_; }
  Renderer& renderer() { return *renderer_; }

  void set_world(const model::WorldDescription& world, const SceneStyle& style);
  /// The moving part of the scene: the posed people (PeopleFigures::mesh(), first, so that their
  /// vertex ranges hold) and then ARI's body.
  void set_dynamic_mesh(const RenderMesh& mesh);

  /// Indices of the cameras with a frame due at sim time t: camera i's k-th frame is due at
  /// k / rate_hz. A frame that could not be taken in time is skipped, not queued. With motion
  /// blur, the next render() of a camera due is its frame at t, compared with its last one.
  std::vector<size_t> due(double time_s);
  /// Starts every camera again for a clock that starts again (the next episode of a batch): the
  /// schedule at sim time 0 (without it, due() would wait for the last run's time) and the
  /// sensors' noise from `seed`, so that an episode's images depend on its seed alone.
  void restart(uint64_t seed);

  /// Renders camera i from its optical frame's pose in the world, with the label image when
  /// `labels` is set and the camera is a pinhole.
  void render(size_t i, const Eigen::Isometry3d& X_world_optical, CameraFrame& out,
              bool labels = false);
  /// The pinhole model of camera i (not for fisheyes).
  const PinholeModel& pinhole(size_t i) const { return pinholes_[i]; }

 private:
  void expose(size_t i, cv::Mat& colour, const cv::Mat& labels, const ImageMotion& motion);
  ImageMotion motion_of(size_t i, const Eigen::Isometry3d& X_world_optical);

  std::vector<CameraSpec> cameras_;
  std::vector<CameraInfo> infos_;
  std::vector<PinholeModel> pinholes_;                      // unused for fisheyes
  std::vector<std::unique_ptr<FisheyeRenderer>> fisheyes_;  // null for pinholes
  std::vector<std::unique_ptr<CameraSensor>> sensors_;      // null without camera effects
  int samples_{1};                                          // per pixel, for anti-aliasing
  std::vector<double> next_due_s_;
  bool motion_blur_{false};
  std::vector<double> frame_time_s_;                   // of each camera's frame due last
  std::vector<FrameMotion> motions_;                   // each camera's, for motion blur
  std::map<uint16_t, Eigen::Vector3f> label_centres_;  // the dynamic mesh's people
  DepthEncoding depth_encoding_;
  std::unique_ptr<Renderer> renderer_;
  RenderedImage scratch_;
};

}  // namespace ari_social_sim::rendering
