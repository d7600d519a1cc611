#include "ari_social_sim/rendering/world_scene.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "ari_social_sim/rendering/doorways.hpp"
#include "ari_social_sim/rendering/furniture.hpp"

namespace ari_social_sim::rendering {
namespace {

const Eigen::Vector3f kFloorColour{0.50f, 0.52f, 0.55f};  // grey-blue sheet vinyl
const Eigen::Vector3f kWallColour{0.86f, 0.85f, 0.80f};
const Eigen::Vector3f kFurnitureColour{0.55f, 0.40f, 0.28f};
const Eigen::Vector3f kCeilingColour{0.93f, 0.93f, 0.91f};
const Eigen::Vector3f kLampColour{1.0f, 0.98f, 0.94f};
constexpr double kSlabThickness = 0.02;  // floor, ceiling and lamp panels
// Facets of the boxes the lamps light per vertex: the floor's finer, for contact shadows of about
// 0.3 m radius.
constexpr double kLitFacetM = 0.25;
constexpr double kFloorFacetM = 0.125;

// The top of the tallest wall: where the ceiling rests. None when the world has no wall.
double ceiling_height(const model::WorldDescription& world, const SceneStyle& style) {
  double top = 0.0;
  for (const model::StaticObject& object : world.objects) {
    if (object.type == model::ShapeType::kWall) {
      top = std::max(top, object.height_m > 0.0 ? object.height_m : style.wall_height_m);
    }
  }
  return top;
}

// A ceiling slab over the whole world at `height` and lamp panels just under it, on a grid.
void add_ceiling(const model::WorldDescription& world, const SceneStyle& style, double height,
                 std::vector<RenderPrimitive>& out) {
  out.push_back(
      solid(PrimitiveShape::kBox,
            upright_pose(world.origin + 0.5 * world.size, height + 0.5 * kSlabThickness, 0.0),
            Eigen::Vector3d(world.size.x(), world.size.y(), kSlabThickness), kCeilingColour,
            Surface::kCeiling));
  const int columns = std::max(1, static_cast<int>(world.size.x() / style.lamp_spacing_m));
  const int rows = std::max(1, static_cast<int>(world.size.y() / style.lamp_spacing_m));
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      const Eigen::Vector2d centre =
          world.origin +
          Eigen::Vector2d((i + 0.5) * world.size.x() / columns, (j + 0.5) * world.size.y() / rows);
      out.push_back(
          solid(PrimitiveShape::kBox, upright_pose(centre, height - 0.5 * kSlabThickness, 0.0),
                Eigen::Vector3d(style.lamp_size_m.x(), style.lamp_size_m.y(), kSlabThickness),
                kLampColour, Surface::kLamp));
    }
  }
}

}  // namespace

std::vector<RenderPrimitive> static_primitives_of(const model::WorldDescription& world,
                                                  const SceneStyle& style) {
  std::vector<RenderPrimitive> out;
  // The floor is a thin slab whose top face is z = 0.
  out.push_back(solid(PrimitiveShape::kBox,
                      upright_pose(world.origin + 0.5 * world.size, -0.5 * kSlabThickness, 0.0),
                      Eigen::Vector3d(world.size.x(), world.size.y(), kSlabThickness), kFloorColour,
                      Surface::kFloor));
  const double ceiling = ceiling_height(world, style);
  if (style.ceiling && ceiling > 0.0) {
    add_ceiling(world, style, ceiling, out);
  }
  for (const Doorway& doorway : doorways_of(world, style.wall_height_m)) {
    const std::vector<RenderPrimitive> parts = doorway_primitives(doorway, kWallColour);
    out.insert(out.end(), parts.begin(), parts.end());
  }

  for (const model::StaticObject& object : world.objects) {
    const bool is_wall = object.type == model::ShapeType::kWall;
    // The world file's height (the physics collides with the same solid); the style's for
    // objects built in code without one.
    const double height = object.height_m > 0.0
                              ? object.height_m
                              : (is_wall ? style.wall_height_m : style.furniture_height_m);
    const Eigen::Vector3f colour = is_wall ? kWallColour : kFurnitureColour;
    const Surface surface = is_wall ? Surface::kWall : Surface::kWood;
    if (!is_wall) {
      if (std::optional<std::vector<RenderPrimitive>> parts = furniture_of(object, height, world)) {
        out.insert(out.end(), parts->begin(), parts->end());
        continue;
      }
    }
    const Eigen::Isometry3d X = upright_pose(object.pose.position, 0.5 * height, object.pose.theta);
    switch (object.type) {
      case model::ShapeType::kWall:
      case model::ShapeType::kBox:
        out.push_back(solid(PrimitiveShape::kBox, X,
                            Eigen::Vector3d(object.size.x(), object.size.y(), height), colour,
                            surface));
        break;
      case model::ShapeType::kCircle:
        out.push_back(solid(PrimitiveShape::kCylinder, X,
                            Eigen::Vector3d(2.0 * object.radius_m, 2.0 * object.radius_m, height),
                            colour, surface));
        break;
      case model::ShapeType::kPolygon: {
        // Polygon vertices are in the map frame; the prism's frame sits on their centroid.
        RenderPrimitive prism =
            solid(PrimitiveShape::kPrism, upright_pose(object.pose.position, 0.5 * height, 0.0),
                  Eigen::Vector3d(1.0, 1.0, height), colour, surface);
        for (const Eigen::Vector2d& point : object.points) {
          prism.outline.emplace_back(point - object.pose.position);
        }
        out.push_back(prism);
        break;
      }
    }
  }
  // The lamps light each vertex: boxes' faces in facets over which their light hardly changes.
  for (RenderPrimitive& primitive : out) {
    if (primitive.shape == PrimitiveShape::kBox) {
      primitive.max_facet_m = primitive.surface == Surface::kFloor ? kFloorFacetM : kLitFacetM;
    }
  }
  return out;
}

}  // namespace ari_social_sim::rendering
