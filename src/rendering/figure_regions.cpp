#include "ari_social_sim/rendering/figure_regions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ari_social_sim::rendering {
namespace {

// Bounds of projected points, in pixel coordinates (centres at integers).
struct Bounds {
  double min_u{std::numeric_limits<double>::max()}, min_v{std::numeric_limits<double>::max()};
  double max_u{std::numeric_limits<double>::lowest()}, max_v{std::numeric_limits<double>::lowest()};
  bool any{false};

  void add(const Eigen::Vector2d& pixel) {
    min_u = std::min(min_u, pixel.x());
    min_v = std::min(min_v, pixel.y());
    max_u = std::max(max_u, pixel.x());
    max_v = std::max(max_v, pixel.y());
    any = true;
  }
  // The pixels whose centres the bounds reach, clipped to the image.
  std::optional<PixelBox> box(const PinholeModel& model) const {
    if (!any) {
      return std::nullopt;
    }
    const auto clamp = [](double value, int high) {
      return static_cast<int>(std::clamp(value, -1.0, static_cast<double>(high) + 1.0));
    };
    const int x0 = std::max(0, clamp(std::lround(min_u), model.width));
    const int y0 = std::max(0, clamp(std::lround(min_v), model.height));
    const int x1 = std::min(model.width, clamp(std::lround(max_u), model.width) + 1);
    const int y1 = std::min(model.height, clamp(std::lround(max_v), model.height) + 1);
    if (x1 <= x0 || y1 <= y0) {
      return std::nullopt;
    }
    return PixelBox{x0, y0, x1 - x0, y1 - y0};
  }
};

}  // namespace

double PixelBox::iou(const PixelBox& other) const {
  const int x0 = std::max(x, other.x), y0 = std::max(y, other.y);
  const int x1 = std::min(x + width, other.x + other.width);
  const int y1 = std::min(y + height, other.y + other.height);
  const double overlap = std::max(0, x1 - x0) * static_cast<double>(std::max(0, y1 - y0));
  const double total = area() + other.area() - overlap;
  return total > 0.0 ? overlap / total : 0.0;
}

std::optional<PixelBox> projected_box(const PinholeModel& model,
                                      const Eigen::Isometry3d& X_optical_frame,
                                      const std::vector<Eigen::Vector3d>& points) {
  Bounds bounds;
  for (const Eigen::Vector3d& point : points) {
    const std::optional<Eigen::Vector2d> pixel = model.project(X_optical_frame * point);
    if (!pixel) {
      return std::nullopt;
    }
    bounds.add(*pixel);
  }
  return bounds.box(model);
}

std::optional<PixelBox> face_region(const HumanFigure& figure, const FigurePose& pose,
                                    const PinholeModel& model,
                                    const Eigen::Isometry3d& X_world_optical) {
  const Eigen::Isometry3d X_optical_head = X_world_optical.inverse() * figure.head_frame(pose);
  // The camera's centre in the head frame: a skin point faces it when its normal points its way.
  const Eigen::Vector3d camera = X_optical_head.inverse().translation();
  Bounds bounds;
  for (const HumanFigure::SurfacePoint& skin : figure.face_surface()) {
    if (skin.normal.dot(camera - skin.point) <= 0.0) {
      continue;
    }
    const std::optional<Eigen::Vector2d> pixel = model.project(X_optical_head * skin.point);
    if (!pixel) {
      return std::nullopt;
    }
    bounds.add(*pixel);
  }
  return bounds.box(model);
}

std::optional<PixelBox> face_outline_region(const HumanFigure& figure, const FigurePose& pose,
                                            const PinholeModel& model,
                                            const Eigen::Isometry3d& X_world_optical) {
  return projected_box(model, X_world_optical.inverse() * figure.head_frame(pose),
                       figure.face_outline());
}

std::optional<PixelBox> body_region(const RenderMesh& mesh, const VertexRange& vertices,
                                    const PinholeModel& model,
                                    const Eigen::Isometry3d& X_world_optical) {
  const Eigen::Isometry3d X_optical_world = X_world_optical.inverse();
  const size_t end = std::min(mesh.vertex_count(), vertices.first + vertices.count);
  Bounds bounds;
  for (size_t i = vertices.first; i < end; ++i) {
    const float* vertex = &mesh.vertices[i * RenderMesh::kFloatsPerVertex];
    const std::optional<Eigen::Vector2d> pixel =
        model.project(X_optical_world * Eigen::Vector3d(vertex[0], vertex[1], vertex[2]));
    if (pixel) {
      bounds.add(*pixel);
    }
  }
  return bounds.box(model);
}

std::optional<PixelBox> posed_body_region(const HumanFigure& figure, const FigurePose& pose,
                                          const PinholeModel& model,
                                          const Eigen::Isometry3d& X_world_optical) {
  RenderMesh mesh;
  figure.append_posed(pose, 0.0f, 0.0f, mesh);
  return body_region(mesh, VertexRange{0, mesh.vertex_count()}, model, X_world_optical);
}

std::optional<std::array<Eigen::Vector2d, 2>> eye_pixels(const HumanFigure& figure,
                                                         const FigurePose& pose,
                                                         const PinholeModel& model,
                                                         const Eigen::Isometry3d& X_world_optical) {
  const Eigen::Isometry3d X_optical_head = X_world_optical.inverse() * figure.head_frame(pose);
  const std::optional<Eigen::Vector2d> right = model.project(X_optical_head * figure.eyes()[0]);
  const std::optional<Eigen::Vector2d> left = model.project(X_optical_head * figure.eyes()[1]);
  if (!right || !left) {
    return std::nullopt;
  }
  return std::array<Eigen::Vector2d, 2>{*right, *left};
}

}  // namespace ari_social_sim::rendering
