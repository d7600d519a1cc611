#include "ari_social_sim/rendering/floor_shade.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::rendering {
namespace {

// Higher than this, a thing's shade on the floor is too faint to see (a reception desk's ledge).
constexpr double kHighestUndersideM = 1.0;
// Narrower than this (chair and table legs), a thing's shade falls between the floor's facets.
constexpr double kNarrowestM = 0.1;
// Lower than this, a thing stands on the floor.
constexpr double kOnTheFloorM = 0.05;
// How dark the rim round the foot of what stands on the floor is, and how far it reaches.
constexpr double kFootShade = 0.35;
constexpr double kFootReachM = 0.12;
constexpr double kDarkestOpenness = 0.3;

bool shades_floor(const RenderPrimitive& primitive) {
  switch (primitive.surface) {
    case Surface::kFloor:
    case Surface::kWall:
    case Surface::kCeiling:
    case Surface::kLamp:
      return false;
    default:
      return true;
  }
}

// The floor-plan footprint of an upright primitive: its frame's x axis and its extents along its
// own x and y (a prism's outline's bounds).
FloorOccluder footprint_of(const RenderPrimitive& primitive) {
  FloorOccluder occluder;
  const Eigen::Vector3d centre = primitive.X_world_shape.translation();
  occluder.centre = centre.head<2>();
  occluder.x_axis = primitive.X_world_shape.linear().col(0).head<2>().normalized();
  occluder.half_size = 0.5 * primitive.size.head<2>();
  if (primitive.shape == PrimitiveShape::kPrism && !primitive.outline.empty()) {
    Eigen::Vector2d low = primitive.outline.front(), high = low;
    for (const Eigen::Vector2d& point : primitive.outline) {
      low = low.cwiseMin(point);
      high = high.cwiseMax(point);
    }
    const Eigen::Vector2d middle = 0.5 * (low + high);
    const Eigen::Vector2d y_axis(-occluder.x_axis.y(), occluder.x_axis.x());
    occluder.centre += middle.x() * occluder.x_axis + middle.y() * y_axis;
    occluder.half_size = 0.5 * (high - low);
  }
  occluder.round =
      primitive.shape == PrimitiveShape::kCylinder || primitive.shape == PrimitiveShape::kSphere;
  occluder.underside_m = std::max(0.0, centre.z() - 0.5 * primitive.size.z());
  return occluder;
}

// The share of the light an occluder leaves at `distance_m` from its footprint: its darkest shade
// fading as a Gaussian of the distance over its fade length.
double openness_past(const FloorOccluder& occluder, double distance_m) {
  // Past three fade lengths under 1e-4 of the light is missing: most of the floor is that far
  // from most of the furniture, and the exponential is the cost of shading it.
  constexpr double kFadesToNoShade = 3.0;
  const double h = occluder.underside_m;
  const bool on_the_floor = h < kOnTheFloorM;
  const double fades = distance_m / (on_the_floor ? kFootReachM : 0.5 * h);
  if (fades > kFadesToNoShade) {
    return 1.0;
  }
  // R^2: the area over pi of a round footprint, or of the ellipse inscribed in a box's.
  const double r2 = occluder.half_size.x() * occluder.half_size.y();
  const double darkest = on_the_floor ? kFootShade : std::min(0.6, 2.0 * r2 / (r2 + h * h));
  return 1.0 - darkest * std::exp(-fades * fades);
}

}  // namespace

double FloorOccluder::distance_to(const Eigen::Vector2d& point) const {
  const Eigen::Vector2d offset = point - centre;
  const Eigen::Vector2d local(offset.dot(x_axis),
                              x_axis.x() * offset.y() - x_axis.y() * offset.x());
  if (round) {
    const Eigen::Vector2d scaled = local.cwiseQuotient(half_size);
    const double norm = scaled.norm();
    // Along the ray from the centre: exact for a circle, close enough for an ellipse.
    return norm <= 1.0 ? 0.0 : (1.0 - 1.0 / norm) * local.norm();
  }
  return (local.cwiseAbs() - half_size).cwiseMax(0.0).norm();
}

std::vector<FloorOccluder> floor_occluders_of(const std::vector<RenderPrimitive>& primitives) {
  std::vector<FloorOccluder> occluders;
  for (const RenderPrimitive& primitive : primitives) {
    if (!shades_floor(primitive)) {
      continue;
    }
    const FloorOccluder occluder = footprint_of(primitive);
    if (occluder.underside_m <= kHighestUndersideM &&
        2.0 * occluder.half_size.minCoeff() >= kNarrowestM) {
      occluders.push_back(occluder);
    }
  }
  return occluders;
}

double floor_openness(const std::vector<FloorOccluder>& occluders, const Eigen::Vector2d& point) {
  double open = 1.0;
  for (const FloorOccluder& occluder : occluders) {
    open *= openness_past(occluder, occluder.distance_to(point));
  }
  return std::max(kDarkestOpenness, open);
}

void shade_floor(const std::vector<FloorOccluder>& occluders, RenderMesh& floor) {
  std::vector<float>& v = floor.vertices;
  for (size_t i = 0; i + RenderMesh::kFloatsPerVertex <= v.size();
       i += RenderMesh::kFloatsPerVertex) {
    const double open = floor_openness(occluders, Eigen::Vector2d(v[i], v[i + 1]));
    const auto shade = static_cast<float>(std::pow(open, 1.0 / 2.2));
    for (int c = 0; c < 3; ++c) {
      v[i + RenderMesh::kColourOffset + c] *= shade;
    }
  }
}

}  // namespace ari_social_sim::rendering
