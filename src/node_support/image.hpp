#pragma once

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include <opencv2/core/mat.hpp>
#include <optional>

#include "ari_social_sim/rendering/camera_model.hpp"

namespace ari_social_sim::nodes {

/// A CV_8UC3 image as `colour_encoding` (its channel order: `rgb8` or `bgr8`), a CV_32FC1 depth
/// image as `32FC1` (metres) or a CV_16UC1 one as `16UC1` (millimetres), REP-118. The header is
/// the caller's.
sensor_msgs::Image to_image_msg(const cv::Mat& image, const char* colour_encoding = "rgb8");
/// A CV_8UC3 RGB image JPEG-encoded, as image_transport's compressed plugin sends it.
sensor_msgs::CompressedImage to_compressed_msg(const cv::Mat& rgb);
sensor_msgs::CameraInfo to_msg(const rendering::CameraInfo& info);

/// The image as BGR (hri_face_detect's encoding), a copy; empty for an encoding other than
/// `rgb8` and `bgr8` or data shorter than its size says.
cv::Mat bgr_of(const sensor_msgs::Image& msg);
/// The pinhole intrinsics of an unrectified camera's info (K); nullopt without a size or focal
/// lengths.
std::optional<rendering::PinholeModel> pinhole_of(const sensor_msgs::CameraInfo& msg);

}  // namespace ari_social_sim::nodes
