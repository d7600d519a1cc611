#include "ari_social_sim/physics/person_shape.hpp"

namespace ari_social_sim::physics {

PersonShape PersonShape::of(const PersonState& state, const PersonShapeConfig& proportions) {
  PersonShape shape;
  shape.id = state.id;
  shape.proportions = proportions;
  shape.face_yaw_rad = state.face_yaw_rad;
  shape.X_map_body.translation() =
      Eigen::Vector3d(state.pose.position.x(), state.pose.position.y(), 0.0);
  shape.X_map_body.linear() =
      Eigen::AngleAxisd(state.pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  shape.head_centre_map = Eigen::Vector3d(state.pose.position.x(), state.pose.position.y(),
                                          proportions.head_centre_height_m);
  return shape;
}

}  // namespace ari_social_sim::physics
