#include "ari_social_sim/rendering/depth_image.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace ari_social_sim::rendering {

const char* encoding_name(DepthEncoding encoding) {
  return core::choice_name(encoding, kDepthEncodings);
}

void clip_depth_range(cv::Mat& depth_m, double min_m, double max_m) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float low = static_cast<float>(min_m), high = static_cast<float>(max_m);
  float* depth = depth_m.ptr<float>();
  const size_t count = depth_m.total();
  for (size_t i = 0; i < count; ++i) {
    // NaN compares false both ways and stays NaN.
    if (depth[i] < low || depth[i] > high) {
      depth[i] = nan;
    }
  }
}

cv::Mat to_millimetres(const cv::Mat& depth_m) {
  cv::Mat millimetres(depth_m.rows, depth_m.cols, CV_16UC1);
  const float* in = depth_m.ptr<float>();
  uint16_t* out = millimetres.ptr<uint16_t>();
  const size_t count = depth_m.total();
  for (size_t i = 0; i < count; ++i) {
    const float mm = std::round(in[i] * 1000.0f);
    out[i] = (std::isfinite(mm) && mm >= 1.0f && mm <= 65535.0f) ? static_cast<uint16_t>(mm) : 0;
  }
  return millimetres;
}

}  // namespace ari_social_sim::rendering
