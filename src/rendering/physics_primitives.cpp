#include "ari_social_sim/rendering/physics_primitives.hpp"

#include <cmath>

namespace ari_social_sim::rendering {
namespace {

// Smallest extent (m) of a shape worth drawing.
constexpr double kSmallestDrawnM = 0.003;

}  // namespace

std::vector<RenderPrimitive> robot_primitives(const physics::RobotModel& model,
                                              const std::vector<Eigen::Isometry3d>& X_world_links) {
  std::vector<RenderPrimitive> out;
  for (size_t link = 0; link < model.links().size(); ++link) {
    for (const physics::LinkShape& visual : model.links()[link].visuals) {
      RenderPrimitive primitive;
      primitive.X_world_shape = X_world_links[link] * visual.X_link_shape;
      primitive.colour = visual.rgba.head<3>().cast<float>();
      switch (visual.type) {
        case physics::LinkShape::Type::kBox:
          primitive.shape = PrimitiveShape::kBox;
          primitive.size = visual.box_size_m;
          break;
        case physics::LinkShape::Type::kCylinder:
          primitive.shape = PrimitiveShape::kCylinder;
          primitive.size = {2.0 * visual.radius_m, 2.0 * visual.radius_m, visual.length_m};
          break;
        case physics::LinkShape::Type::kSphere:
          primitive.shape = PrimitiveShape::kSphere;
          primitive.size = Eigen::Vector3d::Constant(2.0 * visual.radius_m);
          break;
      }
      if (primitive.size.minCoeff() > kSmallestDrawnM) {
        out.push_back(primitive);
      }
    }
  }
  return out;
}

}  // namespace ari_social_sim::rendering
