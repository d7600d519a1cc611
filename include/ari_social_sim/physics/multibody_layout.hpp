#pragma once

#include <Eigen/Geometry>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/physics/robot_model.hpp"

namespace ari_social_sim::physics {

/// One rigid body of a multibody: the child link of a movable joint (or the root link) together
/// with every link fixed to it. Its frame for the dynamics is the centre of mass with the
/// principal axes of inertia, which is what Featherstone's algorithm in Bullet expects.
struct BodyLayout {
  int joint{-1};           // the movable joint this body hangs from; -1 for the root body
  int parent_body{-1};     // -1 for the root body
  int reference_link{0};   // the URDF link whose frame the body's placement is given in
  std::vector<int> links;  // URDF links merged into this body (reference link first)
  double mass_kg{0.0};
  Eigen::Vector3d principal_inertia_kgm2{Eigen::Vector3d::Zero()};
  Eigen::Isometry3d X_reference_com{Eigen::Isometry3d::Identity()};  // principal frame
};

/// Where a URDF link sits: on which body, at which pose in that body's reference frame.
struct LinkPlacement {
  int body{0};
  Eigen::Isometry3d X_reference_link{Eigen::Isometry3d::Identity()};
};

/// How a RobotModel maps onto a multibody: fixed joints merged away (their links' masses and
/// inertias combined with the parallel-axis theorem), one body per movable joint, in tree order
/// so that every body's parent comes first. Body 0 is the root; body k > 0 is multibody link k-1.
///
/// Joints named in `kinematic_joints` are merged like fixed joints (at q = 0) for the dynamics;
/// the simulation sets their positions itself and poses their links from them (AriPhysics does
/// this for ARI's light hand joints and its casters).
class MultibodyLayout {
 public:
  static MultibodyLayout of(const RobotModel& model,
                            const std::set<std::string>& kinematic_joints = {});

  const std::vector<BodyLayout>& bodies() const { return bodies_; }
  /// Indexed like RobotModel::links().
  const std::vector<LinkPlacement>& placements() const { return placements_; }
  /// The body hanging from a movable joint, -1 for fixed joints.
  int body_of_joint(int joint) const { return body_of_joint_[static_cast<size_t>(joint)]; }
  bool is_kinematic(int joint) const { return kinematic_[static_cast<size_t>(joint)]; }

 private:
  std::vector<BodyLayout> bodies_;
  std::vector<LinkPlacement> placements_;
  std::vector<int> body_of_joint_;
  std::vector<bool> kinematic_;  // by joint
};

}  // namespace ari_social_sim::physics
