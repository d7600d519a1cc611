#include "ari_social_sim/physics/multibody_layout.hpp"

#include <Eigen/Eigenvalues>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::physics {
namespace {

// Bodies lighter than this (kg) get this mass and a matching small inertia, so that a pure frame
// hanging from a joint cannot make the mass matrix singular.
constexpr double kMinimumMassKg = 1e-3;
constexpr double kMinimumInertiaKgm2 = 1e-6;

// Mass, centre of mass and inertia about it of the links merged into one body, combined in the
// body's reference frame (parallel-axis theorem), then diagonalised.
void combine_mass(const RobotModel& model, const std::vector<LinkPlacement>& placements,
                  BodyLayout& body) {
  double mass = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const int link : body.links) {
    const LinkInertia& inertia = model.links()[static_cast<size_t>(link)].inertia;
    const Eigen::Isometry3d& X = placements[static_cast<size_t>(link)].X_reference_link;
    mass += inertia.mass_kg;
    moment += inertia.mass_kg * (X * inertia.com_m);
  }
  const Eigen::Vector3d com = mass > 0.0 ? Eigen::Vector3d(moment / mass) : Eigen::Vector3d::Zero();
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  for (const int link : body.links) {
    const LinkInertia& inertia = model.links()[static_cast<size_t>(link)].inertia;
    const Eigen::Isometry3d& X = placements[static_cast<size_t>(link)].X_reference_link;
    const Eigen::Vector3d d = X * inertia.com_m - com;
    I += X.linear() * inertia.inertia_kgm2 * X.linear().transpose() +
         inertia.mass_kg * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(I);
  Eigen::Matrix3d axes = eigen.eigenvectors();
  if (axes.determinant() < 0.0) {
    axes.col(2) = -axes.col(2);  // a rotation, not a reflection
  }
  body.mass_kg = std::max(mass, kMinimumMassKg);
  body.principal_inertia_kgm2 = eigen.eigenvalues().cwiseMax(kMinimumInertiaKgm2);
  body.X_reference_com = Eigen::Isometry3d::Identity();
  body.X_reference_com.linear() = axes;
  body.X_reference_com.translation() = com;
}

}  // namespace

MultibodyLayout MultibodyLayout::of(const RobotModel& model,
                                    const std::set<std::string>& kinematic_joints) {
  MultibodyLayout layout;
  layout.placements_.resize(model.links().size());
  layout.body_of_joint_.assign(model.joints().size(), -1);
  layout.kinematic_.assign(model.joints().size(), false);
  for (const std::string& name : kinematic_joints) {
    const int joint = model.joint_index(name);
    if (joint < 0 || !model.joints()[static_cast<size_t>(joint)].is_movable()) {
      throw core::RequestError(model.name() + ": no movable joint '" + name +
                               "' to simulate kinematically");
    }
    layout.kinematic_[static_cast<size_t>(joint)] = true;
  }
  BodyLayout root;
  root.reference_link = model.root_link();
  layout.bodies_.push_back(root);
  // Links come parents first (RobotModel numbers them depth first), so one pass places them all.
  for (size_t link = 0; link < model.links().size(); ++link) {
    const RobotLink& robot_link = model.links()[link];
    LinkPlacement& placement = layout.placements_[link];
    if (robot_link.parent_joint < 0) {
      placement = {0, Eigen::Isometry3d::Identity()};
    } else {
      const RobotJoint& joint = model.joints()[static_cast<size_t>(robot_link.parent_joint)];
      const LinkPlacement& parent = layout.placements_[static_cast<size_t>(joint.parent_link)];
      if (joint.is_movable() && !layout.kinematic_[static_cast<size_t>(robot_link.parent_joint)]) {
        BodyLayout body;
        body.joint = robot_link.parent_joint;
        body.parent_body = parent.body;
        body.reference_link = static_cast<int>(link);
        layout.body_of_joint_[static_cast<size_t>(robot_link.parent_joint)] =
            static_cast<int>(layout.bodies_.size());
        placement = {static_cast<int>(layout.bodies_.size()), Eigen::Isometry3d::Identity()};
        layout.bodies_.push_back(body);
      } else {
        placement = {parent.body, parent.X_reference_link * joint.X_parent_joint};
      }
    }
    layout.bodies_[static_cast<size_t>(placement.body)].links.push_back(static_cast<int>(link));
  }
  for (BodyLayout& body : layout.bodies_) {
    combine_mass(model, layout.placements_, body);
  }
  return layout;
}

}  // namespace ari_social_sim::physics
