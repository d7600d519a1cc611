#pragma once

#include <vector>

#include "ari_social_sim/physics/render_primitive.hpp"

namespace ari_social_sim::physics {

/// Triangles ready for the GPU: per vertex the world position, outward unit normal, colour and a
/// checker flag, interleaved as kFloatsPerVertex floats, three vertices per triangle.
struct RenderMesh {
  static constexpr int kFloatsPerVertex = 10;
  std::vector<float> vertices;

  size_t vertex_count() const { return vertices.size() / kFloatsPerVertex; }
};

/// Appends the triangles of a primitive to a mesh, counter-clockwise seen from outside. Round
/// shapes use kRoundSegments facets around their axis.
void append_primitive(const RenderPrimitive& primitive, RenderMesh& mesh);
RenderMesh mesh_of(const std::vector<RenderPrimitive>& primitives);

constexpr int kRoundSegments = 32;

}  // namespace ari_social_sim::physics
