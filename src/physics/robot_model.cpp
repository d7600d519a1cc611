#include "ari_social_sim/physics/robot_model.hpp"

#include <urdf_parser/urdf_parser.h>

#include <functional>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/text_file.hpp"

namespace ari_social_sim::physics {
namespace {

Eigen::Isometry3d to_isometry(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  X.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return X;
}

LinkShape to_shape(const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin,
                   const std::string& where) {
  LinkShape shape;
  shape.X_link_shape = to_isometry(origin);
  switch (geometry->type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(*geometry);
      shape.type = LinkShape::Type::kBox;
      shape.box_size_m = {box.dim.x, box.dim.y, box.dim.z};
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
      shape.type = LinkShape::Type::kCylinder;
      shape.radius_m = cylinder.radius;
      shape.length_m = cylinder.length;
      break;
    }
    case urdf::Geometry::SPHERE: {
      shape.type = LinkShape::Type::kSphere;
      shape.radius_m = static_cast<const urdf::Sphere&>(*geometry).radius;
      break;
    }
    default:
      throw core::ConfigError(where + ": expected a box, cylinder or sphere (meshes are not " +
                              "supported), got another geometry");
  }
  return shape;
}

// A link's name, inertia (about its origin, in its frame), visuals and collisions; the caller
// sets its place in the tree.
RobotLink to_link(const urdf::Link& link, int parent_joint, const std::string& source) {
  RobotLink out;
  out.name = link.name;
  out.parent_joint = parent_joint;
  const std::string where = source + ": link " + link.name;
  if (link.inertial) {
    const urdf::Inertial& inertial = *link.inertial;
    const Eigen::Isometry3d X = to_isometry(inertial.origin);
    Eigen::Matrix3d I;
    I << inertial.ixx, inertial.ixy, inertial.ixz, inertial.ixy, inertial.iyy, inertial.iyz,
        inertial.ixz, inertial.iyz, inertial.izz;
    out.inertia.mass_kg = inertial.mass;
    out.inertia.com_m = X.translation();
    out.inertia.inertia_kgm2 = X.linear() * I * X.linear().transpose();
  }
  for (const urdf::VisualSharedPtr& visual : link.visual_array) {
    LinkShape shape = to_shape(visual->geometry, visual->origin, where + " visual");
    if (visual->material) {
      const urdf::Color& c = visual->material->color;
      shape.rgba = {c.r, c.g, c.b, c.a};
    }
    out.visuals.push_back(shape);
  }
  for (const urdf::CollisionSharedPtr& collision : link.collision_array) {
    out.collisions.push_back(
        to_shape(collision->geometry, collision->origin, where + " collision"));
  }
  return out;
}

JointType to_joint_type(int urdf_type, const std::string& where) {
  switch (urdf_type) {
    case urdf::Joint::FIXED:
      return JointType::kFixed;
    case urdf::Joint::REVOLUTE:
      return JointType::kRevolute;
    case urdf::Joint::CONTINUOUS:
      return JointType::kContinuous;
    default:
      throw core::ConfigError(where + ": expected a fixed, revolute or continuous joint");
  }
}

// A joint below the link `parent_link`, checked: a movable joint's axis is a unit vector, a
// revolute joint's limits are ordered.
RobotJoint to_joint(const urdf::Joint& joint, int parent_link, const std::string& source) {
  RobotJoint j;
  j.name = joint.name;
  j.parent_link = parent_link;
  j.X_parent_joint = to_isometry(joint.parent_to_joint_origin_transform);
  j.axis = Eigen::Vector3d(joint.axis.x, joint.axis.y, joint.axis.z);
  const std::string where = source + ": joint " + joint.name;
  j.type = to_joint_type(joint.type, where);
  if (j.is_movable()) {
    if (j.axis.norm() < 1e-9) {
      throw core::ConfigError(where + ": axis: expected a non-zero vector");
    }
    j.axis.normalize();
  }
  if (joint.limits) {
    j.lower_rad = joint.limits->lower;
    j.upper_rad = joint.limits->upper;
    j.max_velocity_rps = joint.limits->velocity;
    j.max_effort_nm = joint.limits->effort;
  }
  if (j.type == JointType::kRevolute && !(j.lower_rad < j.upper_rad)) {
    throw core::ConfigError(where + ": limit: expected lower < upper, got " +
                            std::to_string(j.lower_rad) + " and " + std::to_string(j.upper_rad));
  }
  return j;
}

}  // namespace

RobotModel RobotModel::from_urdf_file(const std::string& path) {
  // ARI's URDF is 33 KB; urdfdom builds a DOM several times the text's size.
  constexpr std::uintmax_t kMaxUrdfBytes = std::uintmax_t{4} * 1024 * 1024;
  return from_urdf_string(core::read_text_file(path, "a URDF file", kMaxUrdfBytes), path);
}

RobotModel RobotModel::from_urdf_string(const std::string& xml, const std::string& source) {
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(xml);
  if (!urdf) {
    throw core::ConfigError(source + ": not a valid URDF (urdfdom could not parse it)");
  }
  RobotModel model;
  model.name_ = urdf->getName();
  model.source_ = source;

  // Links and joints are numbered depth first from the root, children in name order (urdfdom
  // keeps them in maps), so indices do not depend on the order of the XML.
  std::function<void(const urdf::LinkConstSharedPtr&, int)> add_link =
      [&](const urdf::LinkConstSharedPtr& link, int parent_joint) {
        const int index = static_cast<int>(model.links_.size());
        model.links_.push_back(to_link(*link, parent_joint, source));
        if (parent_joint >= 0) {
          model.joints_[parent_joint].child_link = index;
        }
        std::vector<urdf::JointSharedPtr> children = link->child_joints;
        std::sort(children.begin(), children.end(),
                  [](const urdf::JointSharedPtr& a, const urdf::JointSharedPtr& b) {
                    return a->child_link_name < b->child_link_name;
                  });
        for (const urdf::JointSharedPtr& joint : children) {
          const int joint_index = static_cast<int>(model.joints_.size());
          model.joints_.push_back(to_joint(*joint, index, source));
          model.links_[index].child_joints.push_back(joint_index);
          add_link(urdf->getLink(joint->child_link_name), joint_index);
        }
      };
  add_link(urdf->getRoot(), -1);
  model.root_link_ = 0;
  for (size_t i = 0; i < model.links_.size(); ++i) {
    model.link_order_.push_back(static_cast<int>(i));  // depth-first: parents come first
  }
  return model;
}

int RobotModel::link_index(const std::string& name) const {
  for (size_t i = 0; i < links_.size(); ++i) {
    if (links_[i].name == name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

int RobotModel::joint_index(const std::string& name) const {
  for (size_t i = 0; i < joints_.size(); ++i) {
    if (joints_[i].name == name) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

const RobotJoint& RobotModel::joint(const std::string& name) const {
  const int index = joint_index(name);
  if (index < 0) {
    throw core::RequestError(source_ + ": no joint named '" + name + "'");
  }
  return joints_[static_cast<size_t>(index)];
}

std::vector<std::string> RobotModel::movable_joint_names() const {
  std::vector<std::string> names;
  for (const RobotJoint& joint : joints_) {
    if (joint.is_movable()) {
      names.push_back(joint.name);
    }
  }
  return names;
}

Eigen::Isometry3d RobotModel::joint_transform(const RobotJoint& joint, double q) const {
  if (!joint.is_movable()) {
    return joint.X_parent_joint;
  }
  return joint.X_parent_joint * Eigen::Isometry3d(Eigen::AngleAxisd(q, joint.axis));
}

std::vector<Eigen::Isometry3d> RobotModel::link_poses(
    const std::unordered_map<std::string, double>& positions) const {
  std::vector<Eigen::Isometry3d> poses(links_.size(), Eigen::Isometry3d::Identity());
  for (const int index : link_order_) {
    const RobotLink& link = links_[static_cast<size_t>(index)];
    if (link.parent_joint < 0) {
      continue;
    }
    const RobotJoint& joint = joints_[static_cast<size_t>(link.parent_joint)];
    const auto q = positions.find(joint.name);
    poses[static_cast<size_t>(index)] =
        poses[static_cast<size_t>(joint.parent_link)] *
        joint_transform(joint, q == positions.end() ? 0.0 : q->second);
  }
  return poses;
}

Eigen::Isometry3d RobotModel::link_pose(
    const std::string& link, const std::unordered_map<std::string, double>& positions) const {
  const int index = link_index(link);
  if (index < 0) {
    throw core::RequestError(source_ + ": no link named '" + link + "'");
  }
  return link_poses(positions)[static_cast<size_t>(index)];
}

}  // namespace ari_social_sim::physics
