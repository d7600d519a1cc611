#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "ari_social_sim/rendering/camera_rig.hpp"
#include "ari_social_sim/rendering/image_labels.hpp"
#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::rendering {

/// One camera's image at one instant with what it shows of each person.
struct LabelledImage {
  size_t camera{0};  // index into CameraRig::cameras()
  double time_s{0.0};
  cv::Mat colour;  // CV_8UC3, RGB
  std::vector<PersonLabel> labels;
};

/// ARI's pinhole cameras on the world snapshots of one run (an episode): at each snapshot the
/// cameras due (CameraRig::due) see the snapshot's people, posed by PeopleFigures, from ARI's pose
/// and head pan (tilt 0: the 2D world has no head tilt), and each image is labelled
/// (label_people). The dynamic scene holds the people only: ARI's own body is not drawn, so the
/// torso camera does not see ARI's arms or base where the real one would.
class SnapshotCameras {
 public:
  /// Restarts the rig (a run's clock starts at 0) and draws the people's looks and the cameras'
  /// noise from `seed`. Throws core::ConfigError when a camera of the rig is a fisheye: labels
  /// come from pinhole images only. `rig` must outlive this object.
  SnapshotCameras(CameraRig& rig, uint64_t seed);

  /// The images due at the snapshot's time, in the rig's camera order; none when no camera is
  /// due. Throws core::ConfigError when the snapshot has no ARI.
  std::vector<LabelledImage> render_due(const world::WorldSnapshot& snapshot);

 private:
  CameraRig& rig_;
  PeopleFigures figures_;
  std::vector<FigureInput> people_;  // reused from snapshot to snapshot
  CameraFrame frame_;
};

}  // namespace ari_social_sim::rendering
