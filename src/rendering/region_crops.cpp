#include "ari_social_sim/rendering/region_crops.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace ari_social_sim::rendering {
namespace {

cv::Mat letterbox(const cv::Mat& region, int size) {
  const double scale = std::min(double(size) / region.cols, double(size) / region.rows);
  const int width = std::clamp(static_cast<int>(std::lround(region.cols * scale)), 1, size);
  const int height = std::clamp(static_cast<int>(std::lround(region.rows * scale)), 1, size);
  cv::Mat out = cv::Mat::zeros(size, size, region.type());
  cv::Mat scaled;
  cv::resize(region, scaled, cv::Size(width, height), 0.0, 0.0, cv::INTER_LINEAR);
  scaled.copyTo(out(cv::Rect((size - width) / 2, (size - height) / 2, width, height)));
  return out;
}

cv::Rect rect_of(const PixelBox& box) {
  return cv::Rect(box.x, box.y, box.width, box.height);
}

}  // namespace

cv::Mat letterboxed(const cv::Mat& image, const PixelBox& box, int size) {
  return letterbox(image(rect_of(box)), size);
}

cv::Mat aligned_face(const cv::Mat& image, const PixelBox& box, const Eigen::Vector2d& eye_a,
                     const Eigen::Vector2d& eye_b, int size) {
  // From the eye on the image's left to the other: the direction the output's rows follow.
  const Eigen::Vector2d across = eye_a.x() <= eye_b.x() ? eye_b - eye_a : eye_a - eye_b;
  const double angle = across.norm() > 0.0 ? std::atan2(across.y(), across.x()) : 0.0;
  const double c = std::cos(angle), s = std::sin(angle);
  // Output pixel d (centres at integers) samples the image at centre + R(angle) (d - d_centre).
  const Eigen::Vector2d centre(box.x + 0.5 * (box.width - 1), box.y + 0.5 * (box.height - 1));
  const Eigen::Vector2d d_centre(0.5 * (box.width - 1), 0.5 * (box.height - 1));
  const Eigen::Vector2d offset = centre - Eigen::Vector2d(c * d_centre.x() - s * d_centre.y(),
                                                          s * d_centre.x() + c * d_centre.y());
  const cv::Matx23d output_to_image(c, -s, offset.x(), s, c, offset.y());
  cv::Mat turned;
  cv::warpAffine(image, turned, output_to_image, cv::Size(box.width, box.height),
                 cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  return letterbox(turned, size);
}

cv::Mat cut_out(const cv::Mat& image, const PixelBox& box) {
  return image(rect_of(box)).clone();
}

}  // namespace ari_social_sim::rendering
