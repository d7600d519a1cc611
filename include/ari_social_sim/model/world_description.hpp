#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/object_id.hpp"

namespace ari_social_sim::model {

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

/// Largest floor (m per side) a world may have: a building floor, and at the default 0.05 m map
/// resolution 4000 x 4000 cells (16 MB of occupancy grid).
constexpr double kMaxWorldSideM = 200.0;
/// Farthest any coordinate of a world (its origin, an object's position or vertex) may lie from
/// the map origin (m, each axis). Box2D works in float: at 1000 m its resolution is 0.06 mm.
constexpr double kMaxWorldCoordinateM = 1000.0;
/// Most walls and furniture one world may hold.
constexpr size_t kMaxWorldObjects = 2000;

/// Heights of objects whose world file gives none (m): a room's walls, and a table or chair.
constexpr double kDefaultWallHeightM = 2.5;
/// Thickness of a wall whose world file gives none (m).
constexpr double kDefaultWallThicknessM = 0.1;
constexpr double kDefaultFurnitureHeightM = 0.75;

/// The static part of a world: a rectangle of floor and what stands on it. Shared by the 2D world,
/// its occupancy map and (later) the 3D scene. Loaded from worlds/*.yaml by load_world_file.
struct WorldDescription {
  std::string name;
  Eigen::Vector2d origin{0.0, 0.0};  // m, lower-left corner of the floor in the map frame
  Eigen::Vector2d size{0.0, 0.0};    // m, floor extent along x and y
  std::vector<StaticObject> objects;

  bool contains(const Eigen::Vector2d& point) const;
  /// Throws core::ConfigError naming the world and the field unless the origin is finite and within
  /// +-kMaxWorldCoordinateM, the size is finite, > 0 and at most kMaxWorldSideM per side, and there
  /// are at most kMaxWorldObjects objects. load_world_file checks the same with the file's name.
  void validate() const;
};

}  // namespace ari_social_sim::model
