#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <vector>

#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/figure_regions.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"

// The REP-155 images of posed people cut from one camera image, as ROS4HRI's detectors publish
// them (region_crops.hpp): where each face is (face_region, what the renderer labels as face),
// the face scaled into a square and the same with the eyes level, and the body as cut.

namespace ari_social_sim::rendering {

/// One camera image and where the camera was when it was taken.
struct CameraView {
  const cv::Mat& image;  // BGR, camera.width x camera.height
  const PinholeModel& camera;
  Eigen::Isometry3d X_map_optical;
};

/// The face box of each posed person whose face is in the image, by person id.
std::map<uint32_t, PixelBox> face_boxes(const std::vector<PosedPerson>& posed,
                                        const PinholeModel& camera,
                                        const Eigen::Isometry3d& X_map_optical);

/// Which of a face's images to make.
struct FaceImagesWanted {
  bool cropped{false};
  bool aligned{false};
};

/// A face's images, each face_size x face_size; empty when not wanted, and aligned also when an
/// eye is behind the camera.
struct FaceImages {
  cv::Mat cropped;
  cv::Mat aligned;
};

/// `person`'s face images; nullopt when their face is not in the image.
std::optional<FaceImages> face_images(const PosedPerson& person, const CameraView& view,
                                      int face_size, FaceImagesWanted wanted);

/// `person`'s body as cut from the image: the box of their posed figure (posed_body_region);
/// nullopt when their body is not in the image.
std::optional<cv::Mat> body_image(const PosedPerson& person, const CameraView& view);

}  // namespace ari_social_sim::rendering
