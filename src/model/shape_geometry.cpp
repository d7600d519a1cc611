#include "ari_social_sim/model/shape_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::model {
namespace {

using core::number_text;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double area_of(const std::vector<Eigen::Vector2d>& points) {
  double twice = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    twice += cross(points[i], points[(i + 1) % points.size()]);
  }
  return 0.5 * std::abs(twice);
}

// Distance of `p` from the line through `a` and `b` (from `a` when they coincide).
double distance_from_line(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                          const Eigen::Vector2d& b) {
  const Eigen::Vector2d along = b - a;
  const double length = along.norm();
  return length > 0.0 ? std::abs(cross(along, p - a)) / length : (p - a).norm();
}

std::string edge_name(size_t i, size_t n) {
  return std::to_string(i) + "-" + std::to_string((i + 1) % n);
}

std::string duplicate_defect(const std::vector<Eigen::Vector2d>& points) {
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = i + 1; j < points.size(); ++j) {
      const double gap = (points[i] - points[j]).norm();
      if (gap < kBox2dWeldDistanceM) {
        return "duplicate vertices: " + std::to_string(i) + " and " + std::to_string(j) + " are " +
               number_text(gap) + " m apart, expected at least " + number_text(kMinShapeFeatureM) +
               " m";
      }
    }
  }
  return "";
}

// The width of a convex polygon is its smallest extent across one of its edges.
std::string sliver_defect(const std::vector<Eigen::Vector2d>& points) {
  const size_t n = points.size();
  double width = INFINITY, diameter = 0.0;
  size_t thinnest_edge = 0;
  for (size_t i = 0; i < n; ++i) {
    double across = 0.0;
    for (const Eigen::Vector2d& p : points) {
      across = std::max(across, distance_from_line(p, points[i], points[(i + 1) % n]));
      diameter = std::max(diameter, (p - points[i]).norm());
    }
    if (across < width) {
      width = across;
      thinnest_edge = i;
    }
  }
  if (width >= kMinShapeFeatureM) {
    return "";
  }
  return "sliver: " + number_text(width) + " m thin across edge " + edge_name(thinnest_edge, n) +
         " (aspect " + number_text(diameter / width) + ":1), expected at least " +
         number_text(kMinShapeFeatureM) + " m";
}

std::string short_edge_defect(const std::vector<Eigen::Vector2d>& points) {
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i) {
    const double length = (points[(i + 1) % n] - points[i]).norm();
    if (length < kMinShapeFeatureM) {
      return "short edge: edge " + edge_name(i, n) + " is " + number_text(length) +
             " m long, expected at least " + number_text(kMinShapeFeatureM) + " m";
    }
  }
  return "";
}

std::string collinear_defect(const std::vector<Eigen::Vector2d>& points) {
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i) {
    const double off = distance_from_line(points[i], points[(i + n - 1) % n], points[(i + 1) % n]);
    if (off < kMinShapeFeatureM) {
      return "collinear: vertex " + std::to_string(i) + " is " + number_text(off) +
             " m off the line through its neighbours, expected at least " +
             number_text(kMinShapeFeatureM) + " m";
    }
  }
  return "";
}

}  // namespace

std::string polygon_expectation() {
  return std::to_string(kMinPolygonVertices) + " to " + std::to_string(kMaxPolygonVertices) +
         " vertices of a strictly convex polygon, with area at least " +
         number_text(kMinPolygonAreaM2) + " m^2 and every edge, its width and each vertex's " +
         "distance from its neighbours' line at least " + number_text(kMinShapeFeatureM) + " m";
}

bool is_convex(const std::vector<Eigen::Vector2d>& points) {
  int sign = 0;
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = points[(i + 1) % n] - points[i];
    const Eigen::Vector2d next = points[(i + 2) % n] - points[(i + 1) % n];
    const double turn = cross(edge, next);
    if (std::abs(turn) < 1e-9) {
      return false;
    }
    const int s = turn > 0 ? 1 : -1;
    if (sign != 0 && s != sign) {
      return false;
    }
    sign = s;
  }
  return true;
}

std::string polygon_defect(const std::vector<Eigen::Vector2d>& points) {
  if (points.size() < kMinPolygonVertices || points.size() > kMaxPolygonVertices) {
    return std::to_string(points.size()) + " vertices";
  }
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      return "non-finite vertex " + std::to_string(i) + " (" + number_text(points[i].x()) + ", " +
             number_text(points[i].y()) + ")";
    }
  }
  const double area = area_of(points);
  if (area < kMinPolygonAreaM2) {
    return "tiny: area " + number_text(area) + " m^2, expected at least " +
           number_text(kMinPolygonAreaM2) + " m^2";
  }
  for (const auto& defect :
       {duplicate_defect, sliver_defect, short_edge_defect, collinear_defect}) {
    std::string found = defect(points);
    if (!found.empty()) {
      return found;
    }
  }
  return is_convex(points) ? "" : "not convex";
}

std::string static_object_defect(const StaticObject& object) {
  if (!object.pose.position.allFinite() || !std::isfinite(object.pose.theta)) {
    return "non-finite pose";
  }
  const std::string too_small = " below " + number_text(kMinShapeFeatureM) + " m (Box2D's slop)";
  switch (object.type) {
    case ShapeType::kWall:
    case ShapeType::kBox:
      if (!(object.size.minCoeff() >= kMinShapeFeatureM) || !object.size.allFinite()) {
        return "size [" + number_text(object.size.x()) + ", " + number_text(object.size.y()) + "]" +
               too_small + " or not finite";
      }
      return "";
    case ShapeType::kCircle:
      if (!(object.radius_m >= kMinShapeFeatureM) || !std::isfinite(object.radius_m)) {
        return "radius " + number_text(object.radius_m) + too_small + " or not finite";
      }
      return "";
    case ShapeType::kPolygon:
      return polygon_defect(object.points);
  }
  return "";
}

}  // namespace ari_social_sim::model
