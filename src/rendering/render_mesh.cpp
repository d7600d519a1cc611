#include "ari_social_sim/rendering/render_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::rendering {
namespace {

// Writes triangles in the primitive's frame and transforms them to the world as they go in.
class TriangleWriter {
 public:
  TriangleWriter(const RenderPrimitive& primitive, RenderMesh& mesh)
      : primitive_(primitive), mesh_(mesh) {
    // Normals transform with the inverse transpose of the linear part; scaling happens before
    // the writer is called, so the rigid rotation is enough here.
    rotation_ = primitive.X_world_shape.linear();
  }

  // A triangle given counter-clockwise from outside, each vertex with its own local normal.
  void triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                const Eigen::Vector3d& na, const Eigen::Vector3d& nb, const Eigen::Vector3d& nc) {
    vertex(a, na);
    vertex(b, nb);
    vertex(c, nc);
  }
  void flat_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    triangle(a, b, c, n, n, n);
  }
  void flat_quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const Eigen::Vector3d& d) {
    flat_triangle(a, b, c);
    flat_triangle(a, c, d);
  }
  // The parallelogram with corners a, b, b + d - a and d, split into a grid of quads no wider than
  // the primitive's max_facet_m.
  void facet_quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& d) {
    const int across = cells((b - a).norm()), up = cells((d - a).norm());
    const Eigen::Vector3d step_across = (b - a) / across, step_up = (d - a) / up;
    for (int i = 0; i < across; ++i) {
      for (int j = 0; j < up; ++j) {
        const Eigen::Vector3d corner = a + i * step_across + j * step_up;
        flat_quad(corner, corner + step_across, corner + step_across + step_up, corner + step_up);
      }
    }
  }

 private:
  int cells(double length_m) const {
    return primitive_.max_facet_m > 0.0
               ? std::max(1, static_cast<int>(std::ceil(length_m / primitive_.max_facet_m)))
               : 1;
  }

  void vertex(const Eigen::Vector3d& p_local, const Eigen::Vector3d& n_local) {
    const Eigen::Vector3d p = primitive_.X_world_shape * p_local;
    const Eigen::Vector3d n = (rotation_ * n_local).normalized();
    const float values[RenderMesh::kFloatsPerVertex] = {
        static_cast<float>(p.x()),       static_cast<float>(p.y()),
        static_cast<float>(p.z()),       static_cast<float>(n.x()),
        static_cast<float>(n.y()),       static_cast<float>(n.z()),
        primitive_.colour.x(),           primitive_.colour.y(),
        primitive_.colour.z(),           static_cast<float>(primitive_.surface),
        static_cast<float>(p_local.x()), static_cast<float>(p_local.y()),
        static_cast<float>(p_local.z()), 0.0f};
    mesh_.vertices.insert(mesh_.vertices.end(), std::begin(values), std::end(values));
  }

  const RenderPrimitive& primitive_;
  RenderMesh& mesh_;
  Eigen::Matrix3d rotation_;
};

void append_box(const Eigen::Vector3d& half, TriangleWriter& out) {
  // Corner i has x, y, z signs from bits 0, 1, 2.
  auto corner = [&half](int i) {
    return Eigen::Vector3d((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                           (i & 4) ? half.z() : -half.z());
  };
  // Each face counter-clockwise from outside: a corner and its two neighbours.
  out.facet_quad(corner(0), corner(2), corner(1));  // bottom (-z)
  out.facet_quad(corner(4), corner(5), corner(6));  // top (+z)
  out.facet_quad(corner(0), corner(1), corner(4));  // -y
  out.facet_quad(corner(2), corner(6), corner(3));  // +y
  out.facet_quad(corner(0), corner(4), corner(2));  // -x
  out.facet_quad(corner(1), corner(3), corner(5));  // +x
}

// Extrudes a counter-clockwise convex outline from z = -half_height to +half_height. Round
// outlines (cylinders) get smooth side normals: the outward radial direction at each vertex.
void append_prism(const std::vector<Eigen::Vector2d>& ccw, double half_height, bool smooth_sides,
                  const Eigen::Vector2d& radii, TriangleWriter& out) {
  const size_t n = ccw.size();
  auto at = [&](size_t i, double z) { return Eigen::Vector3d(ccw[i].x(), ccw[i].y(), z); };
  auto side_normal = [&](size_t i) {
    // Gradient of x^2/a^2 + y^2/b^2 for ellipses, radial for circles.
    return Eigen::Vector3d(ccw[i].x() / (radii.x() * radii.x()),
                           ccw[i].y() / (radii.y() * radii.y()), 0.0)
        .normalized();
  };
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const Eigen::Vector3d a = at(i, -half_height), b = at(j, -half_height);
    const Eigen::Vector3d c = at(j, half_height), d = at(i, half_height);
    if (smooth_sides) {
      const Eigen::Vector3d ni = side_normal(i), nj = side_normal(j);
      out.triangle(a, b, c, ni, nj, nj);
      out.triangle(a, c, d, ni, nj, ni);
    } else {
      out.flat_quad(a, b, c, d);
    }
  }
  for (size_t i = 1; i + 1 < n; ++i) {
    out.flat_triangle(at(0, half_height), at(i, half_height), at(i + 1, half_height));
    out.flat_triangle(at(0, -half_height), at(i + 1, -half_height), at(i, -half_height));
  }
}

void append_ellipsoid(const Eigen::Vector3d& radii, int segments, TriangleWriter& out) {
  const int rings = segments / 2;
  auto point = [&](int ring, int segment) {
    const double polar = M_PI * ring / rings;
    const double azimuth = 2.0 * M_PI * segment / segments;
    return Eigen::Vector3d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                           std::cos(polar));
  };
  auto scaled = [&](const Eigen::Vector3d& unit) { return unit.cwiseProduct(radii).eval(); };
  auto normal = [&](const Eigen::Vector3d& unit) {
    return unit.cwiseQuotient(radii).normalized().eval();
  };
  for (int ring = 0; ring < rings; ++ring) {
    for (int segment = 0; segment < segments; ++segment) {
      const Eigen::Vector3d a = point(ring, segment), b = point(ring + 1, segment);
      const Eigen::Vector3d c = point(ring + 1, segment + 1), d = point(ring, segment + 1);
      if (ring > 0) {
        out.triangle(scaled(a), scaled(b), scaled(d), normal(a), normal(b), normal(d));
      }
      if (ring + 1 < rings) {
        out.triangle(scaled(b), scaled(c), scaled(d), normal(b), normal(c), normal(d));
      }
    }
  }
}

std::vector<Eigen::Vector2d> counter_clockwise(std::vector<Eigen::Vector2d> outline) {
  double twice_area = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d& a = outline[i];
    const Eigen::Vector2d& b = outline[(i + 1) % outline.size()];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  if (twice_area < 0.0) {
    std::reverse(outline.begin(), outline.end());
  }
  return outline;
}

}  // namespace

void append_primitive(const RenderPrimitive& primitive, RenderMesh& mesh) {
  TriangleWriter out(primitive, mesh);
  const Eigen::Vector3d half = 0.5 * primitive.size;
  switch (primitive.shape) {
    case PrimitiveShape::kBox:
      append_box(half, out);
      break;
    case PrimitiveShape::kCylinder: {
      std::vector<Eigen::Vector2d> circle;
      for (int i = 0; i < primitive.round_segments; ++i) {
        const double angle = 2.0 * M_PI * i / primitive.round_segments;
        circle.emplace_back(half.x() * std::cos(angle), half.y() * std::sin(angle));
      }
      append_prism(circle, half.z(), true, half.head<2>(), out);
      break;
    }
    case PrimitiveShape::kSphere:
      append_ellipsoid(half, primitive.round_segments, out);
      break;
    case PrimitiveShape::kPrism:
      append_prism(counter_clockwise(primitive.outline), half.z(), false, Eigen::Vector2d::Ones(),
                   out);
      break;
  }
}

RenderMesh mesh_of(const std::vector<RenderPrimitive>& primitives) {
  RenderMesh mesh;
  for (const RenderPrimitive& primitive : primitives) {
    append_primitive(primitive, mesh);
  }
  return mesh;
}

void append_moved(const RenderMesh& part, const Eigen::Isometry3f& X_world_part, float label,
                  RenderMesh& out) {
  constexpr int kStride = RenderMesh::kFloatsPerVertex;
  const size_t start = out.vertices.size();
  out.vertices.resize(start + part.vertices.size());
  const Eigen::Matrix3f rotation = X_world_part.linear();
  const Eigen::Vector3f translation = X_world_part.translation();
  const float* from = part.vertices.data();
  float* to = out.vertices.data() + start;
  for (size_t i = 0; i < part.vertex_count(); ++i, from += kStride, to += kStride) {
    const Eigen::Map<const Eigen::Vector3f> position(from), normal(from + 3);
    Eigen::Map<Eigen::Vector3f>{to} = rotation * position + translation;
    Eigen::Map<Eigen::Vector3f>{to + 3} = rotation * normal;
    std::copy(from + 6, from + RenderMesh::kLabelOffset, to + 6);
    to[RenderMesh::kLabelOffset] = label;
  }
}

}  // namespace ari_social_sim::rendering
