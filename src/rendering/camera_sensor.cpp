#include "ari_social_sim/rendering/camera_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::rendering {
namespace {

// The renderer's display values are linear light to the power 1 / 2.2 (its shader), and so are
// the camera's outputs.
constexpr double kGamma = 2.2;
constexpr int kLinearSteps = 4096;     // quantisation of linear light before the output's gamma
constexpr size_t kNormals = 1u << 20;  // a million: no pattern a detector could lock on to
constexpr int kMeteringWidth = 80;     // auto exposure meters a thumbnail of the frame
constexpr int kMeteringHeight = 60;
constexpr double kMinGain = 1.0 / 16.0;

// The colour a BGGR sensor samples at a pixel: blue and green on even rows, green and red on odd.
int bayer_channel(int x, int y) {
  if ((y & 1) == 0) {
    return (x & 1) == 0 ? 2 : 1;
  }
  return (x & 1) == 0 ? 1 : 0;
}

// cos(theta)^k falls off as a lens's natural vignetting does (the cos^4 law at k = 4); k is set
// so that the corners get `corner_illumination`.
cv::Mat vignetting(int width, int height, double horizontal_fov_rad, double corner_illumination) {
  const double focal_px = 0.5 * width / std::tan(0.5 * horizontal_fov_rad);
  const double cx = 0.5 * (width - 1);
  const double cy = 0.5 * (height - 1);
  const double corner_cos = focal_px / std::hypot(std::hypot(cx, cy), focal_px);
  // No vignetting is power 0 (also for a lens so wide that its corners' cosine is 0).
  const double power =
      corner_illumination >= 1.0 ? 0.0 : std::log(corner_illumination) / std::log(corner_cos);
  cv::Mat illumination(height, width, CV_32FC1);
  for (int y = 0; y < height; ++y) {
    float* row = illumination.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      const double cos_theta = focal_px / std::hypot(std::hypot(x - cx, y - cy), focal_px);
      row[x] = static_cast<float>(std::pow(cos_theta, power));
    }
  }
  return illumination;
}

}  // namespace

// The renderer's brightness is taken as the longest exposure a frame allows: auto exposure
// shortens it for a bright scene (fewer electrons, the same relative noise) and amplifies the
// read-out for a dark one, noise and all. `collected` is light as a fraction of the full well.
// Inline in the pixel loops: a call per pixel was a third of the sensor's time.
struct CameraSensor::ReadOut {
  float shot_variance;  // per unit of light
  float read_variance;
  float amplification;
  const uint8_t* to_display;  // kLinearSteps entries

  uint8_t operator()(float collected, float unit_normal) const {
    const float noise = std::sqrt(collected * shot_variance + read_variance) * unit_normal;
    const float out = std::clamp((collected + noise) * amplification, 0.0f, 1.0f);
    return to_display[static_cast<int>(out * (kLinearSteps - 1) + 0.5f)];
  }
};

CameraSensor::CameraSensor(const CameraEffects& effects, int width, int height,
                           double horizontal_fov_rad, uint64_t seed, uint64_t camera_index)
    : effects_(effects),
      relative_illumination_(
          vignetting(width, height, horizontal_fov_rad, effects.corner_illumination)),
      shot_variance_(static_cast<float>(1.0 / effects.full_well_electrons)),
      read_variance_(static_cast<float>(
          std::pow(effects.read_noise_electrons / effects.full_well_electrons, 2.0))),
      to_display_(kLinearSteps),
      camera_index_(camera_index),
      frame_rng_(core::rng_for(seed, core::rng_streams::kCameraSensor, camera_index)) {
  for (int v = 0; v < 256; ++v) {
    to_linear_[v] = static_cast<float>(std::pow(v / 255.0, kGamma));
  }
  for (int i = 0; i < kLinearSteps; ++i) {
    to_display_[i] = static_cast<uint8_t>(
        std::lround(255.0 * std::pow(static_cast<double>(i) / (kLinearSteps - 1), 1.0 / kGamma)));
  }
  // Drawn once: a run restarted with another seed reads them at other offsets.
  unit_normals_.resize(kNormals);
  for (float& n : unit_normals_) {
    n = static_cast<float>(frame_rng_.normal(0.0, 1.0));
  }
  restart(seed);
}

void CameraSensor::restart(uint64_t seed) {
  frame_rng_ = core::rng_for(seed, core::rng_streams::kCameraSensor, camera_index_);
  // Green is the reference an image processor balances the others against.
  white_balance_ = {static_cast<float>(1.0 + frame_rng_.normal(0.0, effects_.white_balance_error)),
                    1.0f,
                    static_cast<float>(1.0 + frame_rng_.normal(0.0, effects_.white_balance_error))};
}

// Meters the frame's mean linear luminance on a thumbnail.
double CameraSensor::exposure_gain(const cv::Mat& rgb) const {
  cv::Mat thumbnail;
  cv::resize(rgb, thumbnail, cv::Size(kMeteringWidth, kMeteringHeight), 0, 0, cv::INTER_AREA);
  double luminance = 0.0;
  for (int y = 0; y < thumbnail.rows; ++y) {
    const cv::Vec3b* row = thumbnail.ptr<cv::Vec3b>(y);
    for (int x = 0; x < thumbnail.cols; ++x) {
      luminance += 0.2126 * to_linear_[row[x][0]] + 0.7152 * to_linear_[row[x][1]] +
                   0.0722 * to_linear_[row[x][2]];
    }
  }
  luminance /= static_cast<double>(thumbnail.total());
  return std::clamp(effects_.exposure_target / std::max(luminance, 1e-6), kMinGain,
                    effects_.max_gain);
}

void CameraSensor::expose(cv::Mat& rgb, const cv::Mat& labels, const ImageMotion& motion) {
  last_gain_ = effects_.auto_exposure ? exposure_gain(rgb) : 1.0;
  const Exposure exposure{static_cast<float>(std::min(last_gain_, 1.0)),
                          static_cast<float>(std::max(last_gain_, 1.0))};
  if (effects_.motion_blur) {
    apply_motion_blur(
        rgb, labels,
        motion.scaled(static_cast<float>(exposure.time * effects_.longest_exposure_s)));
  }
  // Light collected per display value and channel in this frame's exposure time.
  for (int c = 0; c < 3; ++c) {
    for (int v = 0; v < 256; ++v) {
      collected_[c][v] = to_linear_[v] * white_balance_[c] * exposure.time;
    }
  }
  if (effects_.optical_blur_px > 0.0) {
    cv::GaussianBlur(rgb, rgb, cv::Size(0, 0), effects_.optical_blur_px);
  }
  if (effects_.bayer) {
    mosaic_.create(rgb.rows, rgb.cols, CV_8UC1);
    sample_mosaic(rgb, read_out(exposure.amplification));
    // OpenCV names a Bayer pattern by the second row's second and third pixels: BGGR is "RG".
    cv::cvtColor(mosaic_, rgb, cv::COLOR_BayerRG2RGB);
  } else {
    sample_every_channel(rgb, read_out(exposure.amplification));
  }
}

// The normals a row reads, from a fresh offset each row and frame; `count` of them in a row.
const float* CameraSensor::row_normals(size_t count) {
  return unit_normals_.data() + frame_rng_.uniform_index(kNormals - count);
}

CameraSensor::ReadOut CameraSensor::read_out(float amplification) const {
  return {shot_variance_, read_variance_, amplification, to_display_.data()};
}

void CameraSensor::sample_mosaic(const cv::Mat& rgb, const ReadOut& read_out) {
  for (int y = 0; y < rgb.rows; ++y) {
    const cv::Vec3b* in = rgb.ptr<cv::Vec3b>(y);
    const float* illumination = relative_illumination_.ptr<float>(y);
    uint8_t* out = mosaic_.ptr<uint8_t>(y);
    const float* normals = row_normals(static_cast<size_t>(rgb.cols));
    // A row alternates two colours: blue and green on even rows, green and red on odd ones.
    const int even = bayer_channel(0, y);
    const int odd = bayer_channel(1, y);
    for (int x = 0; x < rgb.cols; ++x) {
      const int c = (x & 1) == 0 ? even : odd;
      out[x] = read_out(collected_[c][in[x][c]] * illumination[x], normals[x]);
    }
  }
}

void CameraSensor::sample_every_channel(cv::Mat& rgb, const ReadOut& read_out) {
  for (int y = 0; y < rgb.rows; ++y) {
    uint8_t* pixels = rgb.ptr<uint8_t>(y);
    const float* illumination = relative_illumination_.ptr<float>(y);
    const float* normals = row_normals(3 * static_cast<size_t>(rgb.cols));
    for (int i = 0; i < 3 * rgb.cols; ++i) {
      pixels[i] = read_out(collected_[i % 3][pixels[i]] * illumination[i / 3], normals[i]);
    }
  }
}

}  // namespace ari_social_sim::rendering
