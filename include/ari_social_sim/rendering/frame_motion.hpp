#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <optional>

#include "ari_social_sim/rendering/camera_model.hpp"
#include "ari_social_sim/rendering/motion_blur.hpp"
#include "ari_social_sim/rendering/render_mesh.hpp"

namespace ari_social_sim::rendering {

/// The centre of each label's vertices in a mesh (world frame); label 0 (nothing) left out.
std::map<uint16_t, Eigen::Vector3f> label_centres(const RenderMesh& mesh);

/// One camera's motion from frame to frame: it remembers the last frame's time, pose and people,
/// and tells how far the next frame's background and people moved in its image.
class FrameMotion {
 public:
  /// Image motion at `time_s` over one second, from the change since the previous frame. Nothing
  /// for a first frame, one more than two frame periods (`period_s`) or 0.25 s after the last, a
  /// person new in view, or a label that moved faster than 4 m/s (someone else's now). The
  /// background's motion is that of a point 3 m ahead on the optical axis (the camera's turning,
  /// and its travel seen at a room's depth). Remembers this frame.
  ImageMotion per_second(double time_s, double period_s, const Eigen::Isometry3d& X_world_optical,
                         const PinholeModel& pinhole,
                         const std::map<uint16_t, Eigen::Vector3f>& label_centres);
  /// Forgets the last frame (a run that starts again).
  void restart() { last_time_s_.reset(); }

 private:
  std::optional<double> last_time_s_;
  Eigen::Isometry3d X_world_last_{Eigen::Isometry3d::Identity()};
  std::map<uint16_t, Eigen::Vector3f> last_centres_;
};

}  // namespace ari_social_sim::rendering
