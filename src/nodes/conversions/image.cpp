#include "image.hpp"

#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ari_social_sim::nodes {
namespace {

// image_transport's compressed plugin default.
constexpr int kJpegQuality = 80;

}  // namespace

sensor_msgs::Image to_image_msg(const cv::Mat& image, const char* colour_encoding) {
  sensor_msgs::Image msg;
  msg.height = static_cast<uint32_t>(image.rows);
  msg.width = static_cast<uint32_t>(image.cols);
  switch (image.type()) {
    case CV_8UC3:
      msg.encoding = colour_encoding;
      break;
    case CV_32FC1:
      msg.encoding = "32FC1";
      break;
    default:
      msg.encoding = "16UC1";
      break;
  }
  msg.is_bigendian = 0;
  msg.step = static_cast<uint32_t>(image.cols * image.elemSize());
  msg.data.resize(static_cast<size_t>(msg.step) * image.rows);
  for (int row = 0; row < image.rows; ++row) {
    std::memcpy(&msg.data[static_cast<size_t>(row) * msg.step], image.ptr(row), msg.step);
  }
  return msg;
}

sensor_msgs::CompressedImage to_compressed_msg(const cv::Mat& rgb) {
  sensor_msgs::CompressedImage msg;
  msg.format = "rgb8; jpeg compressed bgr8";
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  cv::imencode(".jpg", bgr, msg.data, {cv::IMWRITE_JPEG_QUALITY, kJpegQuality});
  return msg;
}

sensor_msgs::CameraInfo to_msg(const physics::CameraInfo& info) {
  sensor_msgs::CameraInfo msg;
  msg.width = static_cast<uint32_t>(info.width);
  msg.height = static_cast<uint32_t>(info.height);
  msg.distortion_model = info.distortion_model;
  msg.D = info.D;
  std::copy(info.K.begin(), info.K.end(), msg.K.begin());
  std::copy(info.R.begin(), info.R.end(), msg.R.begin());
  std::copy(info.P.begin(), info.P.end(), msg.P.begin());
  return msg;
}

}  // namespace ari_social_sim::nodes
