#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/world/types.hpp"

namespace ari_social_sim::world {

/// Shape of a piece of static geometry. Walls are boxes drawn as walls.
enum class ShapeType { kWall, kBox, kCircle, kPolygon };

/// One static object (wall or furniture) in the map frame.
struct StaticObject {
  ObjectId id{kNoObject};
  std::string name;
  ShapeType type{ShapeType::kBox};
  core::Pose2 pose;                     // centre and orientation (boxes, walls, circles)
  Eigen::Vector2d size{0.0, 0.0};       // m, full length x width (boxes, walls)
  double radius_m{0.0};                 // circles
  std::vector<Eigen::Vector2d> points;  // convex polygon vertices in the map frame, 3 to 8
  double height_m{0.0};                 // m, standing on the floor; used by the 3D scene only
};

/// Heights of objects whose world file gives none (m): a room's walls, and a table or chair.
constexpr double kDefaultWallHeightM = 2.5;
constexpr double kDefaultFurnitureHeightM = 0.75;

/// The static part of a world: a rectangle of floor and what stands on it. Shared by the 2D world,
/// its occupancy map and (later) the 3D scene. Loaded from worlds/*.yaml by load_world_file.
struct WorldDescription {
  std::string name;
  Eigen::Vector2d origin{0.0, 0.0};  // m, lower-left corner of the floor in the map frame
  Eigen::Vector2d size{0.0, 0.0};    // m, floor extent along x and y
  std::vector<StaticObject> objects;

  bool contains(const Eigen::Vector2d& point) const;
};

}  // namespace ari_social_sim::world
