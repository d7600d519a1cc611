#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include "ari_social_sim/rendering/figure_regions.hpp"

// The images REP-155 asks of a face or body detector, cut from a camera image: ROS4HRI's face
// detector (hri_face_detect) publishes a face's region scaled into a fixed square (cropped) and
// the same turned so that the eyes are level (aligned); a body's region is published as cut.

namespace ari_social_sim::rendering {

/// `box` of `image` scaled to fit a `size` x `size` square keeping its aspect (bilinear), centred,
/// the rest black. `box` must lie inside the image and not be empty.
cv::Mat letterboxed(const cv::Mat& image, const PixelBox& box, int size);

/// As letterboxed, with the region first turned about its centre so that the line through the
/// eyes (pixels, either order) is horizontal. Pixels from outside the image are black.
cv::Mat aligned_face(const cv::Mat& image, const PixelBox& box, const Eigen::Vector2d& eye_a,
                     const Eigen::Vector2d& eye_b, int size);

/// A copy of `box` of `image`, at the image's resolution.
cv::Mat cut_out(const cv::Mat& image, const PixelBox& box);

}  // namespace ari_social_sim::rendering
