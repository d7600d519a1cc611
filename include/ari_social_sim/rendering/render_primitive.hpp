#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace ari_social_sim::rendering {

/// Solid shapes the renderer draws. Every shape is centred on its frame's origin with its height
/// along the frame's z axis.
enum class PrimitiveShape {
  kBox,       // size = full extents along x, y, z
  kCylinder,  // size = (diameter along x, diameter along y, length along z): an elliptic cylinder
  kSphere,    // size = diameters: an ellipsoid
  kPrism,     // convex outline (frame xy) extruded from z = -size.z / 2 to +size.z / 2
};

/// How a surface reflects light. Matte; skin, which also has a colourless highlight where it faces
/// the light (what keeps the features of dark skin visible); and the room's materials, each with
/// a procedural texture in world coordinates (the renderer's shader): floor tiles with grout and
/// speckle, painted walls with a skirting board, wood grain, a ceiling lit by the light it
/// bounces, and lamps that give light; and cloth, whose folds are drawn in the primitive's own
/// frame, so that they move with the part it covers.
enum class Surface {
  kMatte = 0,
  kFloor = 1,
  kSkin = 2,
  kWall = 3,
  kWood = 4,
  kCeiling = 5,
  kLamp = 6,
  kCloth = 7,
};

/// One solid in the world frame with a flat colour, textured by its surface.
struct RenderPrimitive {
  PrimitiveShape shape{PrimitiveShape::kBox};
  Eigen::Isometry3d X_world_shape{Eigen::Isometry3d::Identity()};
  Eigen::Vector3d size{Eigen::Vector3d::Ones()};  // m
  std::vector<Eigen::Vector2d> outline;           // m, prisms only, convex, either winding
  Eigen::Vector3f colour{0.7f, 0.7f, 0.7f};       // linear RGB in [0, 1]
  Surface surface{Surface::kMatte};
  int round_segments{32};  // facets around a cylinder's or ellipsoid's axis; small parts need fewer
  /// Boxes: each face split into a grid of quads no wider than this (m); 0 keeps one quad a face.
  /// The lamps light the scene per vertex, so large surfaces (floors, walls, ceilings) need it.
  double max_facet_m{0.0};
};

/// A pose upright on the floor plan: at (xy, z), turned by `yaw` about world z.
inline Eigen::Isometry3d upright_pose(const Eigen::Vector2d& xy, double z, double yaw) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(xy.x(), xy.y(), z);
  X.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

/// A solid of one colour and surface.
inline RenderPrimitive solid(PrimitiveShape shape, const Eigen::Isometry3d& X_world_shape,
                             const Eigen::Vector3d& size, const Eigen::Vector3f& colour,
                             Surface surface = Surface::kMatte) {
  RenderPrimitive primitive;
  primitive.shape = shape;
  primitive.X_world_shape = X_world_shape;
  primitive.size = size;
  primitive.colour = colour;
  primitive.surface = surface;
  return primitive;
}

}  // namespace ari_social_sim::rendering
