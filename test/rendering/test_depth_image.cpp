#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/rendering/depth_image.hpp"

namespace ari_social_sim::rendering {
namespace {

TEST(DepthImage, ClipsToRangeAndConvertsToMillimetres) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cv::Mat depth = (cv::Mat_<float>(1, 6) << 0.1f, 0.2f, 2.3456f, 10.0f, 12.0f, nan);
  clip_depth_range(depth, 0.2, 10.0);
  EXPECT_TRUE(std::isnan(depth.at<float>(0, 0)));  // closer than 0.2 m
  EXPECT_FLOAT_EQ(depth.at<float>(0, 1), 0.2f);
  EXPECT_TRUE(std::isnan(depth.at<float>(0, 4)));  // beyond 10 m
  const cv::Mat mm = to_millimetres(depth);
  ASSERT_EQ(mm.type(), CV_16UC1);
  EXPECT_EQ(mm.at<uint16_t>(0, 0), 0);  // invalid
  EXPECT_EQ(mm.at<uint16_t>(0, 1), 200);
  EXPECT_EQ(mm.at<uint16_t>(0, 2), 2346);  // 2.3456 m rounds to 2346 mm
  EXPECT_EQ(mm.at<uint16_t>(0, 3), 10000);
  EXPECT_EQ(mm.at<uint16_t>(0, 5), 0);
}

TEST(DepthImage, EncodingNames) {
  EXPECT_STREQ(encoding_name(DepthEncoding::kMetres32F), "32FC1");
  EXPECT_STREQ(encoding_name(DepthEncoding::kMillimetres16U), "16UC1");
  EXPECT_EQ(core::parse_choice("16UC1", kDepthEncodings, "x"), DepthEncoding::kMillimetres16U);
  EXPECT_THROW(core::parse_choice("mono16", kDepthEncodings, "x"), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::rendering
