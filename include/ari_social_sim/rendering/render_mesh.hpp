#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// Triangles ready for the GPU: per vertex the world position, outward unit normal, colour, the
/// surface (Surface), the point in its primitive's own frame (m: textures that move with a part,
/// such as cloth's folds, are drawn from it) and a label, interleaved as kFloatsPerVertex floats,
/// three vertices per triangle. The label is what the renderer's label image holds where the
/// triangle is seen (0: nothing to label, such as walls and the robot).
struct RenderMesh {
  static constexpr int kFloatsPerVertex = 14;
  static constexpr int kColourOffset = 6;
  static constexpr int kShapePointOffset = 10;
  static constexpr int kLabelOffset = 13;
  std::vector<float> vertices;

  size_t vertex_count() const { return vertices.size() / kFloatsPerVertex; }
};

/// Appends the triangles of a primitive to a mesh, counter-clockwise seen from outside. Round
/// shapes use the primitive's round_segments facets around their axis.
void append_primitive(const RenderPrimitive& primitive, RenderMesh& mesh);
RenderMesh mesh_of(const std::vector<RenderPrimitive>& primitives);

/// Appends `part` moved rigidly by X_world_part (positions and normals), with every vertex
/// labelled `label`. Posing a figure this way costs a transform per vertex, not a tessellation.
void append_moved(const RenderMesh& part, const Eigen::Isometry3f& X_world_part, float label,
                  RenderMesh& out);

}  // namespace ari_social_sim::rendering
