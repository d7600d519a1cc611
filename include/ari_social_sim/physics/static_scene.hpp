#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::physics {

/// One wall or piece of furniture as a solid standing on the floor, in the map frame.
struct SceneSolid {
  enum class Type { kBox, kCylinder, kPrism };
  model::ObjectId id{model::kNoObject};
  std::string name;
  Type type{Type::kBox};
  bool is_wall{false};
  /// Centre of the solid (half its height above the floor); x along the box's own x side.
  Eigen::Isometry3d X_map_solid{Eigen::Isometry3d::Identity()};
  Eigen::Vector3d box_size_m{Eigen::Vector3d::Zero()};  // boxes: full edge lengths
  double radius_m{0.0};                                 // cylinders (vertical axis)
  double height_m{0.0};                                 // every type
  std::vector<Eigen::Vector2d> footprint;               // prisms: convex outline, map frame
};

/// The static part of the 3D scene: the floor (the plane z = 0; the world's rectangle says where it
/// is drawn) and the world file's walls and furniture extruded to their heights. The same
/// geometry is the physics' collision world and what the cameras render.
struct StaticScene {
  Eigen::Vector2d floor_origin{Eigen::Vector2d::Zero()};  // m, lower-left corner, map frame
  Eigen::Vector2d floor_size{Eigen::Vector2d::Zero()};    // m
  std::vector<SceneSolid> solids;

  static StaticScene from_world(const model::WorldDescription& world);
};

}  // namespace ari_social_sim::physics
