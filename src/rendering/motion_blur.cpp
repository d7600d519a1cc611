#include "ari_social_sim/rendering/motion_blur.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace ari_social_sim::rendering {
namespace {

// Shorter smears are lost in the optics' blur (0.6 px, CameraEffects::optical_blur_px).
constexpr float kSmallestBlurPx = 1.0f;

bool blurs(const Eigen::Vector2f& motion) {
  return motion.norm() >= kSmallestBlurPx;
}

// `image` smeared evenly along `motion`, each pixel the mean of the `motion`-long segment through
// it: the path of a point while the shutter is open. A box filter along the rows or columns when
// the motion strays less than half a pixel from them, else along the rows of a copy turned so that
// the motion runs along them (a box filter costs the same for any length; convolving a line
// kernel, which OpenCV does through the DFT, cost 29 ms a walker). `border`: how the image goes
// on past its edges.
cv::Mat smeared(const cv::Mat& image, const Eigen::Vector2f& motion, int border) {
  const int length = std::max(1, static_cast<int>(std::lround(motion.norm())));
  const double angle = std::atan2(motion.y(), motion.x());
  cv::Mat out;
  if (std::abs(motion.y()) < 0.5f) {
    cv::blur(image, out, cv::Size(length, 1), cv::Point(-1, -1), border);
    return out;
  }
  if (std::abs(motion.x()) < 0.5f) {
    cv::blur(image, out, cv::Size(1, length), cv::Point(-1, -1), border);
    return out;
  }
  // A canvas just large enough for the turned image, the image in its middle.
  const double c = std::abs(std::cos(angle));
  const double s = std::abs(std::sin(angle));
  const cv::Size canvas(static_cast<int>(std::ceil(image.cols * c + image.rows * s)) + 2,
                        static_cast<int>(std::ceil(image.cols * s + image.rows * c)) + 2);
  const cv::Point2f centre(0.5f * (image.cols - 1), 0.5f * (image.rows - 1));
  cv::Mat to_canvas = cv::getRotationMatrix2D(centre, angle * 180.0 / M_PI, 1.0);
  to_canvas.at<double>(0, 2) += 0.5 * (canvas.width - image.cols);
  to_canvas.at<double>(1, 2) += 0.5 * (canvas.height - image.rows);
  cv::Mat turned;
  cv::warpAffine(image, turned, to_canvas, canvas, cv::INTER_LINEAR, border);
  cv::blur(turned, turned, cv::Size(length, 1), cv::Point(-1, -1), border);
  cv::warpAffine(turned, out, to_canvas, image.size(), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 border);
  return out;
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

// Three channels of colour and, as a fourth, the first channel of `weight` (CV_32FC3).
cv::Mat with_weight(const cv::Mat& colour, const cv::Mat& weight) {
  std::vector<cv::Mat> channels;
  cv::split(colour, channels);
  cv::Mat weight_channel;
  cv::extractChannel(weight, weight_channel, 0);
  channels.push_back(weight_channel);
  cv::Mat out;
  cv::merge(channels, out);
  return out;
}

// What the camera would see behind a person, where they stand: the image there averaged along
// the motion from the pixels that are not theirs (normalised convolution) over twice the smear's
// length, so that the pixels their passing uncovers show the background, not the person again.
// `image`: CV_8UC3; `mask3`: the person's pixels, CV_32FC3 in {0, 1}.
cv::Mat behind_person(const cv::Mat& image, const cv::Mat& mask3, const Eigen::Vector2f& shift) {
  cv::Mat seen;
  image.convertTo(seen, CV_32FC3);
  const cv::Mat open = cv::Scalar::all(1.0) - mask3;
  // The light around and its weight smeared together, as four channels.
  std::vector<cv::Mat> around_weight;
  cv::split(smeared(with_weight(seen.mul(open), open), 2.0f * shift, cv::BORDER_CONSTANT),
            around_weight);
  const cv::Mat weight = cv::max(around_weight[3], 1e-3);
  cv::Mat filled;
  cv::merge(std::vector<cv::Mat>{around_weight[0] / weight, around_weight[1] / weight,
                                 around_weight[2] / weight},
            filled);
  return seen.mul(open) + filled.mul(mask3);
}

// One person's pixels smeared along `shift` over `out` (the image behind them): light from the
// person where they passed while the shutter was open, the rest from what is behind.
void smear_person(const cv::Mat& sharp, const cv::Mat& labels, uint16_t label, cv::Rect box,
                  const Eigen::Vector2f& shift, cv::Mat& out) {
  const int margin = static_cast<int>(std::ceil(shift.norm())) + 1;
  box = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
        cv::Rect(0, 0, out.cols, out.rows);
  cv::Mat mask, mask3, person;
  cv::compare(labels(box), label, mask, cv::CMP_EQ);
  mask.convertTo(mask, CV_32FC1, 1.0 / 255.0);
  cv::merge(std::vector<cv::Mat>{mask, mask, mask}, mask3);
  sharp(box).convertTo(person, CV_32FC3);
  person = person.mul(mask3);
  std::vector<cv::Mat> light_coverage;
  cv::split(smeared(with_weight(person, mask3), shift, cv::BORDER_CONSTANT), light_coverage);
  cv::Mat light, coverage;
  cv::merge(std::vector<cv::Mat>(light_coverage.begin(), light_coverage.begin() + 3), light);
  cv::merge(std::vector<cv::Mat>(3, light_coverage[3]), coverage);
  const cv::Mat behind = behind_person(out(box), mask3, shift);
  cv::Mat blended = light + (cv::Scalar::all(1.0) - coverage).mul(behind);
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
    smeared(rgb, motion.background, cv::BORDER_REPLICATE).copyTo(rgb);
  }
  for (const auto& [label, shift] : motion.labelled) {
    if (label < boxes.size() && !boxes[label].empty()) {
      smear_person(sharp, labels, label, boxes[label], shift, rgb);
    }
  }
}

}  // namespace ari_social_sim::rendering
