#pragma once

// Scoring stock OpenCV detectors against the rendered images' labels, shared by the detector study
// test (test_detector_study) and the study over the shipped scenarios (bench/detector_study).

#include <algorithm>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/objdetect.hpp>
#include <string>
#include <vector>

#include "ari_social_sim/rendering/image_labels.hpp"

namespace ari_social_sim::rendering::detector_scoring {

constexpr char kFrontalAlt2Cascade[] =
    "/usr/share/opencv4/haarcascades/haarcascade_frontalface_alt2.xml";
constexpr char kFrontalDefaultCascade[] =
    "/usr/share/opencv4/haarcascades/haarcascade_frontalface_default.xml";
constexpr char kProfileCascade[] = "/usr/share/opencv4/haarcascades/haarcascade_profileface.xml";
constexpr double kMatchIou = 0.5;

inline PixelBox box_of(const cv::Rect& rect) {
  return {rect.x, rect.y, rect.width, rect.height};
}

/// A detection centred on the face's box, as tall as the face within a factor of two. The profile
/// cascade's square window holds the ear and the cheek as well as the face, while a turned face's
/// box is narrow (from the head's middle to the nose's tip, about 0.6 of its height): IoU >= 0.5
/// would need a detection of nearly exactly the face's height, so profile detections are also
/// scored this way (docs/cameras.md).
inline bool centred_on(const cv::Rect& detection, const PixelBox& face) {
  const double u = detection.x + 0.5 * detection.width, v = detection.y + 0.5 * detection.height;
  return u >= face.x && u <= face.x + face.width && v >= face.y && v <= face.y + face.height &&
         detection.height >= 0.5 * face.height && detection.height <= 2.0 * face.height;
}

inline bool any_overlaps(const std::vector<cv::Rect>& detections, const PixelBox& truth) {
  return std::any_of(detections.begin(), detections.end(), [&truth](const cv::Rect& detection) {
    return box_of(detection).iou(truth) >= kMatchIou;
  });
}

inline bool any_centred(const std::vector<cv::Rect>& detections, const PixelBox& face) {
  return std::any_of(detections.begin(), detections.end(),
                     [&face](const cv::Rect& detection) { return centred_on(detection, face); });
}

/// The face cascades as the detector study runs them: scale step 1.1, 3 neighbours, 24 pixels
/// and up.
inline std::vector<cv::Rect> cascade_faces(cv::CascadeClassifier& cascade, const cv::Mat& grey) {
  std::vector<cv::Rect> faces;
  cascade.detectMultiScale(grey, faces, 1.1, 3, 0, cv::Size(24, 24));
  return faces;
}

/// The profile cascade was trained on faces looking one way (to the image's left): it runs on the
/// image and on its mirror, whose detections are mirrored back.
inline std::vector<cv::Rect> profile_faces(cv::CascadeClassifier& cascade, const cv::Mat& grey) {
  std::vector<cv::Rect> faces = cascade_faces(cascade, grey);
  cv::Mat mirror;
  cv::flip(grey, mirror, 1);
  for (const cv::Rect& face : cascade_faces(cascade, mirror)) {
    faces.emplace_back(grey.cols - face.x - face.width, face.y, face.width, face.height);
  }
  return faces;
}

/// The person inside a HOG window: Dalal and Triggs' 64 x 128 training windows hold the person
/// with a 16-pixel margin on every side, so the person box is the window less a quarter of its
/// width and an eighth of its height on each side.
inline PixelBox person_in_hog_window(const cv::Rect& window) {
  return {window.x + window.width / 4, window.y + window.height / 8, window.width / 2,
          window.height * 3 / 4};
}

/// The person OpenCV's Python people detection sample draws in a HOG window: the window less 15 %
/// of its width and 5 % of its height on each side (it finds the window "slightly larger" than
/// the person). That box is about 0.39 as wide as tall, a standing person's proportion.
inline PixelBox person_drawn_in_hog_window(const cv::Rect& window) {
  const int side = static_cast<int>(0.15 * window.width);
  const int top = static_cast<int>(0.05 * window.height);
  return {window.x + side, window.y + top, window.width - 2 * side, window.height - 2 * top};
}

/// The detections for which `hits(detection, label)` holds for some label.
template <typename Hits>
int detections_where(const std::vector<cv::Rect>& detections,
                     const std::vector<PersonLabel>& labels, Hits hits) {
  return static_cast<int>(
      std::count_if(detections.begin(), detections.end(), [&](const cv::Rect& d) {
        return std::any_of(labels.begin(), labels.end(),
                           [&](const PersonLabel& label) { return hits(d, label); });
      }));
}

/// Whether a detection falls on the person: its centre in their box.
inline bool on_person(const cv::Rect& detection, const PersonLabel& label) {
  return label.body_box.contains(detection.x + detection.width / 2,
                                 detection.y + detection.height / 2);
}

/// The detections that fall on someone: on turned heads when every face is turned. Those on the
/// room (tiles, furniture) are the empty frames' count.
inline int detections_on_people(const std::vector<cv::Rect>& detections,
                                const std::vector<PersonLabel>& labels) {
  return detections_where(detections, labels, on_person);
}

/// Of those, the boxes that match a labelled face (IoU >= 0.5): on turned heads, a frontal cascade
/// boxing a face at the edge of the poses it was trained on, rather than a window on an ear, an
/// eye, hair or clothes.
inline int detections_on_faces(const std::vector<cv::Rect>& detections,
                               const std::vector<PersonLabel>& labels) {
  return detections_where(detections, labels, [](const cv::Rect& d, const PersonLabel& label) {
    return label.face_box && box_of(d).iou(*label.face_box) >= kMatchIou;
  });
}

/// Of those, the detections on someone whose face turns `min_yaw_deg` or more from the camera
/// (over 90: facing away): windows on heads turned past the frontal poses, rather than on a face
/// at their edge.
inline int detections_on_people_turned(const std::vector<cv::Rect>& detections,
                                       const std::vector<PersonLabel>& labels, double min_yaw_deg) {
  return detections_where(detections, labels, [=](const cv::Rect& d, const PersonLabel& label) {
    return label.face_yaw_deg >= min_yaw_deg && on_person(d, label);
  });
}

/// Detection rate in bins of one quantity, printed as a Markdown table.
class RateTable {
 public:
  RateTable(std::string quantity, std::vector<double> edges)
      : quantity_(std::move(quantity)),
        edges_(std::move(edges)),
        found_(edges_.size() - 1),
        total_(edges_.size() - 1) {}

  void add(double value, bool found) {
    for (size_t i = 0; i + 1 < edges_.size(); ++i) {
      if (value >= edges_[i] && value < edges_[i + 1]) {
        total_[i] += 1;
        found_[i] += found ? 1 : 0;
      }
    }
  }

  void print(const char* detector) const {
    std::printf("| %s: %s | found | of | rate |\n|---|---|---|---|\n", detector, quantity_.c_str());
    for (size_t i = 0; i < total_.size(); ++i) {
      std::printf(
          "| %g to %g | %d | %d | %s |\n", edges_[i], edges_[i + 1], found_[i], total_[i],
          total_[i] > 0 ? (std::to_string(100 * found_[i] / total_[i]) + " %").c_str() : "-");
    }
  }

 private:
  std::string quantity_;
  std::vector<double> edges_;
  std::vector<int> found_, total_;
};

}  // namespace ari_social_sim::rendering::detector_scoring
