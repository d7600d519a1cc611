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

sensor_msgs::CameraInfo to_msg(const rendering::CameraInfo& info) {
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

cv::Mat bgr_of(const sensor_msgs::Image& msg) {
  if ((msg.encoding != "rgb8" && msg.encoding != "bgr8") || msg.step < msg.width * 3 ||
      msg.data.size() < static_cast<size_t>(msg.step) * msg.height) {
    return {};
  }
  const cv::Mat view(static_cast<int>(msg.height), static_cast<int>(msg.width), CV_8UC3,
                     const_cast<uint8_t*>(msg.data.data()), msg.step);
  cv::Mat bgr;
  if (msg.encoding == "rgb8") {
    cv::cvtColor(view, bgr, cv::COLOR_RGB2BGR);
  } else {
    bgr = view.clone();
  }
  return bgr;
}

std::optional<rendering::PinholeModel> pinhole_of(const sensor_msgs::CameraInfo& msg) {
  if (msg.width == 0 || msg.height == 0 || msg.K[0] <= 0.0 || msg.K[4] <= 0.0) {
    return std::nullopt;
  }
  rendering::PinholeModel model;
  model.width = static_cast<int>(msg.width);
  model.height = static_cast<int>(msg.height);
  model.fx = msg.K[0];
  model.cx = msg.K[2];
  model.fy = msg.K[4];
  model.cy = msg.K[5];
  return model;
}

}  // namespace ari_social_sim::nodes
