#include "ari_social_sim/physics/static_scene.hpp"

namespace ari_social_sim::physics {

StaticScene StaticScene::from_world(const model::WorldDescription& world) {
  StaticScene scene;
  scene.floor_origin = world.origin;
  scene.floor_size = world.size;
  for (const model::StaticObject& object : world.objects) {
    SceneSolid solid;
    solid.id = object.id;
    solid.name = object.name;
    solid.height_m = object.height_m;
    solid.X_map_solid.translation() =
        Eigen::Vector3d(object.pose.position.x(), object.pose.position.y(), 0.5 * object.height_m);
    solid.X_map_solid.linear() =
        Eigen::AngleAxisd(object.pose.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    switch (object.type) {
      case model::ShapeType::kWall:
      case model::ShapeType::kBox:
        solid.type = SceneSolid::Type::kBox;
        solid.is_wall = object.type == model::ShapeType::kWall;
        solid.box_size_m = {object.size.x(), object.size.y(), object.height_m};
        break;
      case model::ShapeType::kCircle:
        solid.type = SceneSolid::Type::kCylinder;
        solid.radius_m = object.radius_m;
        break;
      case model::ShapeType::kPolygon:
        solid.type = SceneSolid::Type::kPrism;
        solid.footprint = object.points;
        break;
    }
    scene.solids.push_back(solid);
  }
  return scene;
}

}  // namespace ari_social_sim::physics
