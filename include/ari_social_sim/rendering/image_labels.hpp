#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/figure_regions.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/rendering/renderer.hpp"

namespace ari_social_sim::rendering {

/// What one camera image shows of one person: the ground truth a detector is scored against.
struct PersonLabel {
  uint32_t person_id{0};
  PixelBox body_box;  // around the person's visible pixels
  int visible_pixels{0};
  /// Share of the person's pixels hidden by something in front (other people, furniture, ARI):
  /// 1 - visible / what they would cover alone in this image. Parts outside the image count
  /// as neither.
  double occlusion{0.0};
  bool truncated{false};  // the person reaches the image's border
  /// Around the face's outline (hairline, chin, cheeks) projected; only when the face is turned
  /// less than 90 degrees from the camera and no more than half of it is hidden.
  std::optional<PixelBox> face_box;
  double face_occlusion{1.0};  // as occlusion, for the face's pixels
  double face_yaw_deg{180.0};  // angle between where the face points and the camera, 0 frontal
  double distance_m{0.0};      // from the camera to the person's feet centre, horizontally
  bool mask{false};            // the person wears a mask over nose and mouth
  int skin_tone{0};            // HumanAppearance::skin_tone: 1 the lightest to 6 the darkest
  bool seated{false};  // sitting, or more than halfway down while sitting down or standing up
};

struct LabelOptions {
  int min_visible_pixels{20};      // fewer and the person is not labelled
  double max_face_occlusion{0.5};  // a face more hidden has no face box
};

/// Labels every person visible in a rendered image. `labels` is the image's label channel
/// (ViewOptions::labels) rendered with people.mesh() at the start of the renderer's dynamic mesh;
/// the renderer is used again to draw each visible person alone for the occlusion.
std::vector<PersonLabel> label_people(Renderer& renderer, const PinholeModel& model,
                                      const Eigen::Isometry3d& X_world_optical,
                                      const PeopleFigures& people, const cv::Mat& labels,
                                      const LabelOptions& options = {});

}  // namespace ari_social_sim::rendering
