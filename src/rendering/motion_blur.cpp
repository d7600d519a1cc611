#include "ari_social_sim/rendering/motion_blur.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace ari_social_sim::rendering {
namespace {

constexpr float kSmallestBlurPx = 0.5f;

bool blurs(const Eigen::Vector2f& motion) {
  return motion.norm() >= kSmallestBlurPx;
}

// A normalised kernel that spreads a point evenly along `motion`, centred: the path of a point
// while the shutter is open. Sampled four times per pixel of length and splatted bilinearly, so
// that a motion of a fraction of a pixel or at any angle keeps its length.
cv::Mat line_kernel(const Eigen::Vector2f& motion) {
  const int radius = static_cast<int>(std::ceil(0.5f * motion.norm())) + 1;
  const int size = 2 * radius + 1;
  cv::Mat kernel = cv::Mat::zeros(size, size, CV_32FC1);
  const int samples = std::max(2, static_cast<int>(std::ceil(4.0f * motion.norm())));
  for (int k = 0; k < samples; ++k) {
    const Eigen::Vector2f at =
        Eigen::Vector2f::Constant(radius) + motion * (static_cast<float>(k) / (samples - 1) - 0.5f);
    const int x = static_cast<int>(std::floor(at.x()));
    const int y = static_cast<int>(std::floor(at.y()));
    const float fx = at.x() - x;
    const float fy = at.y() - y;
    kernel.at<float>(y, x) += (1 - fx) * (1 - fy);
    kernel.at<float>(y, x + 1) += fx * (1 - fy);
    kernel.at<float>(y + 1, x) += (1 - fx) * fy;
    kernel.at<float>(y + 1, x + 1) += fx * fy;
  }
  return kernel / cv::sum(kernel)[0];
}

// The box around each moving label's pixels, indexed by label (empty for the others).
std::vector<cv::Rect> boxes_of(const cv::Mat& labels, const ImageMotion& motion) {
  std::vector<cv::Rect> boxes(motion.labelled.empty() ? 0 : motion.labelled.rbegin()->first + 1);
  std::vector<bool> moving(boxes.size(), false);
  for (const auto& [label, shift] : motion.labelled) {
    moving[label] = blurs(shift);
  }
  for (int y = 0; y < labels.rows; ++y) {
    const uint16_t* row = labels.ptr<uint16_t>(y);
    for (int x = 0; x < labels.cols; ++x) {
      const uint16_t label = row[x];
      if (label >= boxes.size() || !moving[label]) {
        continue;
      }
      cv::Rect& box = boxes[label];
      box = box.empty() ? cv::Rect(x, y, 1, 1) : (box | cv::Rect(x, y, 1, 1));
    }
  }
  return boxes;
}

// What the camera would see behind a person, where they stand: the image there averaged along
// the motion from the pixels that are not theirs (normalised convolution) over twice the smear's
// length, so that the pixels their passing uncovers show the background, not the person again.
// `image`: CV_8UC3; `mask3`: the person's pixels, CV_32FC3 in {0, 1}.
cv::Mat behind_person(const cv::Mat& image, const cv::Mat& mask3, const Eigen::Vector2f& shift) {
  const cv::Mat kernel = line_kernel(2.0f * shift);
  cv::Mat around, weight, seen;
  image.convertTo(seen, CV_32FC3);
  const cv::Mat open = cv::Scalar::all(1.0) - mask3;
  cv::filter2D(seen.mul(open), around, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_CONSTANT);
  cv::filter2D(open, weight, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_CONSTANT);
  const cv::Mat filled = around / cv::max(weight, 1e-3);
  return seen.mul(open) + filled.mul(mask3);
}

// One person's pixels smeared along `shift` over `out` (the image behind them): light from the
// person where they passed while the shutter was open, the rest from what is behind.
void smear_person(const cv::Mat& sharp, const cv::Mat& labels, uint16_t label, cv::Rect box,
                  const Eigen::Vector2f& shift, cv::Mat& out) {
  const cv::Mat kernel = line_kernel(shift);
  const int margin = kernel.rows / 2;
  box = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
        cv::Rect(0, 0, out.cols, out.rows);
  cv::Mat mask, mask3, person, smeared, coverage;
  cv::compare(labels(box), label, mask, cv::CMP_EQ);
  mask.convertTo(mask, CV_32FC1, 1.0 / 255.0);
  cv::merge(std::vector<cv::Mat>{mask, mask, mask}, mask3);
  sharp(box).convertTo(person, CV_32FC3);
  person = person.mul(mask3);
  cv::filter2D(person, smeared, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_CONSTANT);
  cv::filter2D(mask3, coverage, -1, kernel, cv::Point(-1, -1), 0, cv::BORDER_CONSTANT);
  const cv::Mat behind = behind_person(out(box), mask3, shift);
  cv::Mat blended = smeared + (cv::Scalar::all(1.0) - coverage).mul(behind);
  cv::Mat out_box = out(box);  // converted in place: same size and type
  blended.convertTo(out_box, CV_8UC3);
}

}  // namespace

ImageMotion ImageMotion::scaled(float fraction) const {
  ImageMotion out{background * fraction, labelled};
  for (auto& [label, shift] : out.labelled) {
    shift *= fraction;
  }
  return out;
}

void apply_motion_blur(cv::Mat& rgb, const cv::Mat& labels, const ImageMotion& motion) {
  const std::vector<cv::Rect> boxes =
      labels.empty() ? std::vector<cv::Rect>{} : boxes_of(labels, motion);
  const bool people_move =
      std::any_of(boxes.begin(), boxes.end(), [](const cv::Rect& box) { return !box.empty(); });
  if (!blurs(motion.background) && !people_move) {
    return;
  }
  const cv::Mat sharp = people_move ? rgb.clone() : cv::Mat();
  if (blurs(motion.background)) {
    cv::filter2D(rgb, rgb, -1, line_kernel(motion.background), cv::Point(-1, -1), 0,
                 cv::BORDER_REPLICATE);
  }
  for (const auto& [label, shift] : motion.labelled) {
    if (label < boxes.size() && !boxes[label].empty()) {
      smear_person(sharp, labels, label, boxes[label], shift, rgb);
    }
  }
}

}  // namespace ari_social_sim::rendering
