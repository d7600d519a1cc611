#include "ari_social_sim/physics/point_head.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::physics {
namespace {

// Signed angle about `axis` (unit) that turns `from` onto `to`, both projected on the plane
// normal to the axis.
double angle_about(const Eigen::Vector3d& axis, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& to) {
  const Eigen::Vector3d a = from - axis * axis.dot(from);
  const Eigen::Vector3d b = to - axis * axis.dot(to);
  if (a.norm() < 1e-9 || b.norm() < 1e-9) {
    return 0.0;
  }
  return std::atan2(axis.dot(a.cross(b)), a.dot(b));
}

bool descends_from(const RobotModel& model, int link, int joint) {
  while (link >= 0) {
    const int parent_joint = model.links()[static_cast<size_t>(link)].parent_joint;
    if (parent_joint == joint) {
      return true;
    }
    if (parent_joint < 0) {
      return false;
    }
    link = model.joints()[static_cast<size_t>(parent_joint)].parent_link;
  }
  return false;
}

}  // namespace

PointHeadSolver::PointHeadSolver(const RobotModel& model, std::string pan_joint,
                                 std::string tilt_joint)
    : model_(model), pan_joint_(std::move(pan_joint)), tilt_joint_(std::move(tilt_joint)) {
  model_.joint(pan_joint_);  // throws if absent
  model_.joint(tilt_joint_);
}

double PointHeadSolver::pointing_error(
    const Eigen::Vector3d& target_root, const Eigen::Vector3d& pointing_axis,
    const std::string& pointing_frame,
    const std::unordered_map<std::string, double>& positions) const {
  const Eigen::Isometry3d X = model_.link_pose(pointing_frame, positions);
  const Eigen::Vector3d aimed = X.linear() * pointing_axis.normalized();
  const Eigen::Vector3d wanted = (target_root - X.translation()).normalized();
  return std::acos(std::clamp(aimed.dot(wanted), -1.0, 1.0));
}

HeadAim PointHeadSolver::solve(const Eigen::Vector3d& target_root,
                               const Eigen::Vector3d& pointing_axis,
                               const std::string& pointing_frame,
                               const std::unordered_map<std::string, double>& positions) const {
  const int frame = model_.link_index(pointing_frame);
  if (frame < 0) {
    throw core::RequestError("pointing_frame: no frame named '" + pointing_frame + "' on ARI");
  }
  if (!descends_from(model_, frame, model_.joint_index(tilt_joint_))) {
    throw core::RequestError("pointing_frame: '" + pointing_frame + "' does not move with " +
                             tilt_joint_);
  }
  if (pointing_axis.norm() < 1e-9) {
    throw core::RequestError("pointing_axis: expected a non-zero vector");
  }
  const Eigen::Vector3d axis = pointing_axis.normalized();
  const RobotJoint& pan = model_.joint(pan_joint_);
  const RobotJoint& tilt = model_.joint(tilt_joint_);
  const int pan_child = pan.child_link;
  const int tilt_child = tilt.child_link;

  std::unordered_map<std::string, double> q = positions;
  HeadAim aim;
  // Alternating pan and tilt corrections: each aligns the projections on the plane its axis
  // spins, which converges in a few rounds because the frame's offset from the axes is small
  // compared with the distance to the target.
  for (int round = 0; round < 30; ++round) {
    const std::vector<Eigen::Isometry3d> poses = model_.link_poses(q);
    const Eigen::Isometry3d& X_frame = poses[static_cast<size_t>(frame)];
    const Eigen::Vector3d to_target = target_root - X_frame.translation();
    if (to_target.norm() < 1e-6) {
      throw core::RequestError("target: the point is at the pointing frame's origin");
    }
    const Eigen::Vector3d pan_axis = poses[static_cast<size_t>(pan_child)].linear() * pan.axis;
    const double pan_step = angle_about(pan_axis, X_frame.linear() * axis, to_target);
    q[pan_joint_] = std::clamp(q[pan_joint_] + pan_step, pan.lower_rad, pan.upper_rad);

    const std::vector<Eigen::Isometry3d> panned = model_.link_poses(q);
    const Eigen::Isometry3d& X_frame2 = panned[static_cast<size_t>(frame)];
    const Eigen::Vector3d tilt_axis = panned[static_cast<size_t>(tilt_child)].linear() * tilt.axis;
    const double tilt_step =
        angle_about(tilt_axis, X_frame2.linear() * axis, target_root - X_frame2.translation());
    q[tilt_joint_] = std::clamp(q[tilt_joint_] + tilt_step, tilt.lower_rad, tilt.upper_rad);
    if (std::abs(pan_step) < 1e-7 && std::abs(tilt_step) < 1e-7) {
      break;
    }
  }
  aim.pan_rad = q[pan_joint_];
  aim.tilt_rad = q[tilt_joint_];
  aim.error_rad = pointing_error(target_root, axis, pointing_frame, q);
  aim.limited = aim.pan_rad <= pan.lower_rad || aim.pan_rad >= pan.upper_rad ||
                aim.tilt_rad <= tilt.lower_rad || aim.tilt_rad >= tilt.upper_rad;
  return aim;
}

}  // namespace ari_social_sim::physics
