#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/shape_geometry.hpp"
#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::model {

inline constexpr core::Choice<ShapeType> kShapeTypes[] = {{ShapeType::kWall, "wall"},
                                                          {ShapeType::kBox, "box"},
                                                          {ShapeType::kCircle, "circle"},
                                                          {ShapeType::kPolygon, "polygon"}};

/// Coordinates and extents in a world file (m): bounded, so that Box2D's float keeps its
/// resolution and the occupancy grid its size.
inline const core::Bounds kWorldCoordinate =
    core::between(-kMaxWorldCoordinateM, kMaxWorldCoordinateM);
inline const core::Bounds kWorldExtent{0.0, kMaxWorldSideM, true};
/// A shape's sides and radius (m): at least Box2D's slop (shape_geometry.hpp).
inline const core::Bounds kShapeExtent = core::between(kMinShapeFeatureM, kMaxWorldSideM);

/// One `objects[i]` entry of a world file as written: each shape type has its own keys (a wall
/// `from`, `to` and `thickness`; a box `position`, `orientation` and `size`; a circle `position`
/// and `radius`; a polygon `points`), and a key of another type is refused.
struct WorldObjectEntry {
  ShapeType type{ShapeType::kBox};
  ObjectId id{kNoObject};
  std::string name;
  std::optional<Eigen::Vector2d> from;
  std::optional<Eigen::Vector2d> to;
  std::optional<double> thickness;
  std::optional<Eigen::Vector2d> position;
  std::optional<double> orientation;
  std::optional<Eigen::Vector2d> size;
  std::optional<double> radius;
  std::optional<std::vector<Eigen::Vector2d>> points;
  std::optional<double> height;

  template <class V>
  void visit(V& v) {
    v.choice(core::required("type"), type, "the shape", kShapeTypes);
    v.field("id", id, "object id; 0 = automatic (from 1000 on, skipping ids given)");
    v.field("name", name, "shown in rviz");
    v.field("from", from, "m, wall: one end of its centre line", kWorldCoordinate);
    v.field("to", to, "m, wall: the other end", kWorldCoordinate);
    v.field("thickness", thickness, "m, wall: default 0.1", kShapeExtent);
    v.field("position", position, "m, box and circle: centre in the map frame", kWorldCoordinate);
    v.field("orientation", orientation, "rad, box: heading of its length (default 0)",
            core::between(-core::kMaxHeadingRad, core::kMaxHeadingRad));
    v.field("size", size, "m, box: [length, width]", kShapeExtent);
    v.field("radius", radius, "m, circle", kShapeExtent);
    v.field(
        "points", points,
        "m, polygon: 3 to 8 vertices of a strictly convex polygon, map frame; edges and width at "
        "least 0.005 m (Box2D's slop)",
        kWorldCoordinate);
    v.field("height", height,
            "m, standing on the floor (3D scene); default 2.5 for walls, 0.75 "
            "for furniture",
            kWorldExtent);
    v.rule("type", shape_mismatch().empty(),
           "an entry with the keys of its type: a wall from and to (thickness), a box position "
           "and size (orientation), a circle position and radius, a polygon points; any type id, "
           "name and height",
           shape_mismatch());
    const double wall_length = from && to ? (*to - *from).norm() : kMinShapeFeatureM;
    v.rule("to", !(type == ShapeType::kWall && wall_length < kMinShapeFeatureM),
           "a point at least " + core::number_text(kMinShapeFeatureM) +
               " m from 'from' (a wall needs a length)",
           core::number_text(wall_length) + " m from 'from'");
    const std::string polygon =
        type == ShapeType::kPolygon && points ? polygon_defect(*points) : "";
    v.rule("points", polygon.empty(), polygon_expectation(), polygon);
  }

  /// "" when the keys given are those of the entry's type, else what is wrong: "a circle without
  /// radius", "a circle with from".
  std::string shape_mismatch() const;
  /// What the entry describes, once its keys are checked.
  StaticObject object() const;
};

/// A world file as written (format in docs/world.md, every key in docs/parameters.md):
///
///   name: two_room_flat
///   origin: [0, 0]          # m, lower-left corner of the floor
///   size: [10, 6]           # m
///   objects:
///     - {type: wall, from: [0, 0], to: [10, 0], thickness: 0.1}
///     - {type: box, name: couch, position: [2, 5], orientation: 0, size: [2, 0.8]}
///     - {type: circle, name: table, position: [7, 2], radius: 0.4}
///     - {type: polygon, name: desk, points: [[1, 1], [2, 1], [2, 2]]}
struct WorldFile {
  std::string name;
  Eigen::Vector2d origin{0.0, 0.0};
  Eigen::Vector2d size{0.0, 0.0};
  std::vector<WorldObjectEntry> objects;

  template <class V>
  void visit(V& v) {
    v.field(core::required("name"), name, "the world's name, in messages and rviz");
    v.field("origin", origin, "m, lower-left corner of the floor in the map frame",
            kWorldCoordinate);
    v.field(core::required("size"), size, "m, the floor's extent along x and y", kWorldExtent);
    v.list(core::required("objects"), objects, "walls and furniture", kMaxWorldObjects);
    const std::optional<ObjectId> repeated = repeated_id();
    v.rule("objects", !repeated, "ids used by one object each",
           repeated ? "id " + std::to_string(*repeated) + " twice" : "");
  }

  /// An id two entries give, if any.
  std::optional<ObjectId> repeated_id() const;
  /// The world the file describes, with automatic ids for the objects that have none.
  WorldDescription description() const;
};

/// Reads a world file. Throws core::ConfigError naming the file, the entry and the field on any
/// malformed value (unknown type, missing field, a key of another type, wrong type, non-positive
/// size, a polygon Box2D cannot take (polygon_defect), duplicate id).
WorldDescription load_world_file(const std::string& path);
/// The same from an already-parsed mapping (tests and inline worlds).
WorldDescription parse_world(const core::YamlMap& root);

}  // namespace ari_social_sim::model
