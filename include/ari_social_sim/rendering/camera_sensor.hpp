#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/rendering/camera_effects.hpp"
#include "ari_social_sim/rendering/motion_blur.hpp"

namespace ari_social_sim::rendering {

/// One camera's sensor and image processor: turns the light a frame's pixels received (the
/// renderer's display values) into what the camera outputs. In order: auto exposure, motion blur
/// (when on), the optics'
/// blur, vignetting, white balance, a Bayer mosaic, photon shot noise and read noise in
/// electrons, quantisation with the output's gamma, demosaicing. Deterministic: the k-th frame of a
/// camera has the same noise for the same seed, whatever the other cameras do.
class CameraSensor {
 public:
  /// `horizontal_fov_rad` places the corners for vignetting; `camera_index` picks the camera's
  /// random stream (core::rng_streams::kCameraSensor) of `seed`.
  CameraSensor(const CameraEffects& effects, int width, int height, double horizontal_fov_rad,
               uint64_t seed, uint64_t camera_index);

  /// Starts the camera's frames again from `seed`, as a new run (an episode) does: its white
  /// balance and every frame's noise then come from that seed alone.
  void restart(uint64_t seed);

  /// Exposes the next frame in place. `rgb`: CV_8UC3, RGB, of the size given at construction.
  /// With motion blur on, `motion` (over a second) smears it for the exposure time auto exposure
  /// chose, people found by `labels` (CV_16UC1; may be empty).
  void expose(cv::Mat& rgb, const cv::Mat& labels = cv::Mat(),
              const ImageMotion& motion = ImageMotion());
  /// The gain auto exposure chose for the last frame (1 without it).
  double last_gain() const { return last_gain_; }

 private:
  // Auto exposure's choice split as a camera makes it: a shorter exposure time for a bright scene,
  // gain on the read-out for a dark one.
  struct Exposure {
    float time{1.0f};           // <= 1: a fraction of the longest exposure
    float amplification{1.0f};  // >= 1
  };

  struct ReadOut;  // one pixel's noise and quantisation, inlined in the pixel loops

  double exposure_gain(const cv::Mat& rgb) const;
  ReadOut read_out(float amplification) const;
  const float* row_normals(size_t count);
  void sample_mosaic(const cv::Mat& rgb, const ReadOut& read_out);
  void sample_every_channel(cv::Mat& rgb, const ReadOut& read_out);

  CameraEffects effects_;
  cv::Mat relative_illumination_;         // CV_32FC1: vignetting, 1 at the centre
  std::array<float, 3> white_balance_{};  // gains per channel (R, G, B)
  float shot_variance_;                   // per unit of light, as a fraction of the full well
  float read_variance_;
  std::array<float, 256> to_linear_{};                 // display value -> linear light
  std::array<std::array<float, 256>, 3> collected_{};  // this frame's, per channel and value
  std::vector<uint8_t> to_display_;  // linear light in 4096 steps -> display value
  std::vector<float> unit_normals_;  // drawn once; each frame reads them at new offsets
  uint64_t camera_index_;
  core::Rng frame_rng_;
  cv::Mat mosaic_;  // CV_8UC1, the Bayer image of the last frame
  double last_gain_{1.0};
};

}  // namespace ari_social_sim::rendering
