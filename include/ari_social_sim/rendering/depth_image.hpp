#pragma once

#include <opencv2/core/mat.hpp>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::rendering {

/// The two depth encodings of REP-118.
enum class DepthEncoding {
  kMetres32F,       // "32FC1": float metres, NaN where there is no valid reading
  kMillimetres16U,  // "16UC1": unsigned millimetres, 0 where there is no valid reading
};

/// The sensor_msgs/Image encoding strings of the depth encodings.
inline constexpr core::Choice<DepthEncoding> kDepthEncodings[] = {
    {DepthEncoding::kMetres32F, "32FC1"}, {DepthEncoding::kMillimetres16U, "16UC1"}};

/// "32FC1" or "16UC1".
const char* encoding_name(DepthEncoding encoding);

/// Marks readings outside the sensor's range [min_m, max_m] invalid (NaN), in place (CV_32FC1).
void clip_depth_range(cv::Mat& depth_m, double min_m, double max_m);

/// Float metres (NaN invalid) to 16-bit millimetres rounded to the nearest (0 invalid). Readings
/// beyond 65.535 m do not fit and become invalid.
cv::Mat to_millimetres(const cv::Mat& depth_m);

}  // namespace ari_social_sim::rendering
