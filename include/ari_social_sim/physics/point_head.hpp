#pragma once

#include <Eigen/Geometry>
#include <string>
#include <unordered_map>

#include "ari_social_sim/physics/robot_model.hpp"

namespace ari_social_sim::physics {

/// Pan and tilt that aim an axis of a head-mounted frame at a point, and the angle left over.
struct HeadAim {
  double pan_rad{0.0};
  double tilt_rad{0.0};
  double error_rad{0.0};  // angle between the aimed axis and the direction to the target
  bool limited{false};    // a joint limit stopped the head short of the target
};

/// What PAL's head_action does for /head_controller/point_head_action: finds head_1 (pan) and
/// head_2 (tilt) positions that aim `pointing_axis` of `pointing_frame` at a target, with the
/// frame's offset from the joint axes taken into account (so a camera above and ahead of the tilt
/// axis looks exactly at the point, not parallel to the ray from the axis).
class PointHeadSolver {
 public:
  /// Throws core::RequestError if the model lacks the pan or tilt joint.
  PointHeadSolver(const RobotModel& model, std::string pan_joint = "head_1_joint",
                  std::string tilt_joint = "head_2_joint");

  /// `target_root`: the point in the model's root frame (base_footprint). `pointing_frame` must
  /// be a descendant of the tilt joint; `pointing_axis` is a non-zero vector in it. Other joints
  /// stay at `positions`. Throws core::RequestError for an unknown frame, a frame the head does
  /// not move, a zero axis, or a target at the frame's origin.
  HeadAim solve(const Eigen::Vector3d& target_root, const Eigen::Vector3d& pointing_axis,
                const std::string& pointing_frame,
                const std::unordered_map<std::string, double>& positions) const;

  /// Angle (rad) between the axis and the direction to the target at the given joint positions.
  double pointing_error(const Eigen::Vector3d& target_root, const Eigen::Vector3d& pointing_axis,
                        const std::string& pointing_frame,
                        const std::unordered_map<std::string, double>& positions) const;

 private:
  const RobotModel& model_;
  std::string pan_joint_;
  std::string tilt_joint_;
};

}  // namespace ari_social_sim::physics
