#pragma once

#include <Eigen/Geometry>
#include <string>
#include <unordered_map>
#include <vector>

namespace ari_social_sim::physics {

/// A primitive shape of a link, placed in the link's frame. Meshes are not supported: ARI's model
/// is built from primitives (urdf/ari.urdf).
struct LinkShape {
  enum class Type { kBox, kCylinder, kSphere };
  Type type{Type::kBox};
  Eigen::Vector3d box_size_m{Eigen::Vector3d::Zero()};  // full edge lengths (boxes)
  double radius_m{0.0};                                 // cylinders (axis = shape z) and spheres
  double length_m{0.0};                                 // cylinders
  Eigen::Isometry3d X_link_shape{Eigen::Isometry3d::Identity()};
  Eigen::Vector4d rgba{0.8, 0.8, 0.8, 1.0};  // visual colour (material colour, else grey)
};

/// Mass properties of a link: mass and the inertia tensor about the centre of mass, both in the
/// link's frame.
struct LinkInertia {
  double mass_kg{0.0};
  Eigen::Vector3d com_m{Eigen::Vector3d::Zero()};
  Eigen::Matrix3d inertia_kgm2{Eigen::Matrix3d::Zero()};
};

struct RobotLink {
  std::string name;
  int parent_joint{-1};  // index into RobotModel::joints(); -1 for the root
  std::vector<int> child_joints;
  LinkInertia inertia;  // zero mass when the URDF gives none (pure frames)
  std::vector<LinkShape> visuals;
  std::vector<LinkShape> collisions;
};

enum class JointType { kFixed, kRevolute, kContinuous };

struct RobotJoint {
  std::string name;
  JointType type{JointType::kFixed};
  int parent_link{-1};
  int child_link{-1};
  Eigen::Isometry3d X_parent_joint{Eigen::Isometry3d::Identity()};  // origin at q = 0
  Eigen::Vector3d axis{Eigen::Vector3d::UnitZ()};                   // unit, in the child frame
  double lower_rad{0.0};  // position limits (revolute joints only)
  double upper_rad{0.0};
  double max_velocity_rps{0.0};  // 0 when the URDF gives none
  double max_effort_nm{0.0};

  bool is_movable() const { return type != JointType::kFixed; }
};

/// A robot's kinematic tree read from URDF with urdfdom: links, joints, limits, mass properties and
/// primitive geometry, plus forward kinematics at given joint positions. Immutable once built.
class RobotModel {
 public:
  /// Parses a URDF file. Throws core::ConfigError naming the file when it cannot be read or parsed,
  /// or when it uses what the simulator does not support (prismatic, planar or floating joints,
  /// mesh geometry).
  static RobotModel from_urdf_file(const std::string& path);
  /// The same from URDF text; `source` names it in messages.
  static RobotModel from_urdf_string(const std::string& xml, const std::string& source);

  const std::string& name() const { return name_; }
  const std::vector<RobotLink>& links() const { return links_; }
  const std::vector<RobotJoint>& joints() const { return joints_; }
  int root_link() const { return root_link_; }
  /// -1 when absent.
  int link_index(const std::string& name) const;
  int joint_index(const std::string& name) const;
  const RobotJoint& joint(const std::string& name) const;
  /// Names of the movable joints, in URDF tree order (depth first from the root).
  std::vector<std::string> movable_joint_names() const;

  /// Pose of every link in the root frame at the given joint positions (rad, by joint name;
  /// joints not listed are at 0), indexed like links().
  std::vector<Eigen::Isometry3d> link_poses(
      const std::unordered_map<std::string, double>& positions) const;
  /// Pose of one link in the root frame; throws core::RequestError for an unknown link.
  Eigen::Isometry3d link_pose(const std::string& link,
                              const std::unordered_map<std::string, double>& positions) const;

  /// Transform from a joint's parent link to its child at position q.
  Eigen::Isometry3d joint_transform(const RobotJoint& joint, double q) const;

 private:
  std::string name_;
  std::string source_;
  std::vector<RobotLink> links_;
  std::vector<RobotJoint> joints_;
  std::vector<int> link_order_;  // parents before children
  int root_link_{-1};
};

}  // namespace ari_social_sim::physics
