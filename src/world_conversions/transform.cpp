#include "transform.hpp"

namespace ari_social_sim::nodes {

Eigen::Isometry3d isometry_of(const geometry_msgs::Transform& transform) {
  const geometry_msgs::Quaternion& q = transform.rotation;
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
  X.translation() =
      Eigen::Vector3d(transform.translation.x, transform.translation.y, transform.translation.z);
  return X;
}

}  // namespace ari_social_sim::nodes
