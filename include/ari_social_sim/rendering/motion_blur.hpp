#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <opencv2/core/mat.hpp>

namespace ari_social_sim::rendering {

/// How far things moved across a camera's image while its shutter was open, in pixels: the
/// background, by the camera's own motion, and each labelled person (label image values).
struct ImageMotion {
  Eigen::Vector2f background{0.0f, 0.0f};
  std::map<uint16_t, Eigen::Vector2f> labelled;

  /// The same motion over `fraction` of the time.
  ImageMotion scaled(float fraction) const;
};

/// Smears an image as a shutter open during `motion` does: the whole frame along the background's
/// motion, then each person's pixels (where `labels`, CV_16UC1, holds their label) along their own,
/// over what the first step left behind them. Motions under a pixel leave pixels as they are.
/// `rgb`: CV_8UC3.
void apply_motion_blur(cv::Mat& rgb, const cv::Mat& labels, const ImageMotion& motion);

}  // namespace ari_social_sim::rendering
