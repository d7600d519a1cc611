#include "ari_social_sim/rendering/furniture.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace ari_social_sim::rendering {
namespace {

const Eigen::Vector3f kFrameColour{0.30f, 0.30f, 0.32f};   // chair legs, metal
const Eigen::Vector3f kFabricColour{0.22f, 0.33f, 0.50f};  // seats and backs
const Eigen::Vector3f kTableTopColour{0.62f, 0.47f, 0.32f};
const Eigen::Vector3f kPotColour{0.62f, 0.33f, 0.22f};
const Eigen::Vector3f kLeafColour{0.20f, 0.45f, 0.18f};
const Eigen::Vector3f kDispenserColour{0.90f, 0.90f, 0.88f};
const Eigen::Vector3f kBottleColour{0.55f, 0.72f, 0.90f};
const Eigen::Vector3f kPanelColour{0.80f, 0.80f, 0.78f};  // a desk's laminate front
const Eigen::Vector3f kPlinthColour{0.25f, 0.25f, 0.27f};
constexpr double kSeatPitchM = 0.5;  // one seat per half metre of a row
constexpr double kLegRadiusM = 0.02;

bool named(const model::StaticObject& object, const char* word) {
  return object.name.find(word) != std::string::npos;
}

// A solid with fewer facets around its axis: the parts are small.
RenderPrimitive part(PrimitiveShape shape, const Eigen::Isometry3d& X_world_part,
                     const Eigen::Vector3d& size, const Eigen::Vector3f& colour,
                     Surface surface = Surface::kMatte) {
  RenderPrimitive primitive = solid(shape, X_world_part, size, colour, surface);
  primitive.round_segments = 16;
  return primitive;
}

// The object's frame on the floor: its footprint's centre and yaw.
Eigen::Isometry3d object_frame(const model::StaticObject& object) {
  return upright_pose(object.pose.position, 0.0, object.pose.theta);
}

Eigen::Isometry3d offset(const Eigen::Isometry3d& X, const Eigen::Vector3d& in_frame) {
  Eigen::Isometry3d moved = X;
  moved.translation() += X.linear() * in_frame;
  return moved;
}

// Whether a map point lies inside another object's footprint (walls and boxes, circles).
bool inside(const model::StaticObject& object, const Eigen::Vector2d& point) {
  const Eigen::Vector2d d = point - object.pose.position;
  if (object.type == model::ShapeType::kCircle) {
    return d.norm() <= object.radius_m;
  }
  if (object.type == model::ShapeType::kPolygon) {
    return false;
  }
  const Eigen::Vector2d local = Eigen::Rotation2Dd(-object.pose.theta) * d;
  return std::abs(local.x()) <= 0.5 * object.size.x() &&
         std::abs(local.y()) <= 0.5 * object.size.y();
}

// Of `sides` of an object's footprint (unit vectors of its frame), the one whose probe, stepped
// out from the footprint's edge, first lands in another object that `counts`; `sides[0]` when
// none does within `reach_m`.
template <class Counts>
Eigen::Vector2d nearest_side(const model::StaticObject& object,
                             const std::vector<Eigen::Vector2d>& sides,
                             const model::WorldDescription& world, double reach_m, Counts counts) {
  Eigen::Vector2d best = sides[0];
  double nearest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& side : sides) {
    const double half_depth = 0.5 * std::abs(side.dot(object.size));
    for (double gap = 0.05; gap < reach_m && gap < nearest; gap += 0.05) {
      const Eigen::Vector2d probe = object.pose.position + Eigen::Rotation2Dd(object.pose.theta) *
                                                               ((half_depth + gap) * side);
      const bool hit = std::any_of(
          world.objects.begin(), world.objects.end(), [&](const model::StaticObject& other) {
            return &other != &object && counts(other) && inside(other, probe);
          });
      if (hit) {
        nearest = gap;
        best = side;
      }
    }
  }
  return best;
}

// The side of a chair's footprint with the nearest wall or furniture behind it within 1 m: where
// its back goes; -x when there is none.
Eigen::Vector2d back_side(const model::StaticObject& chair, const model::WorldDescription& world) {
  return nearest_side(chair, {{-1, 0}, {1, 0}, {0, -1}, {0, 1}}, world, 1.0,
                      [](const model::StaticObject&) { return true; });
}

// Of a desk's two long sides, the one facing the nearest wall within 3 m: where the staff sit.
Eigen::Vector2d staff_side(const model::StaticObject& desk, const model::WorldDescription& world) {
  const bool long_along_x = desk.size.x() >= desk.size.y();
  const Eigen::Vector2d across = long_along_x ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(1, 0);
  return nearest_side(desk, {-across, across}, world, 3.0, [](const model::StaticObject& other) {
    return other.type == model::ShapeType::kWall;
  });
}

// Chairs side by side along the footprint's long edge, backs on `back` (a unit side).
std::vector<RenderPrimitive> chairs(const model::StaticObject& object, double height_m,
                                    const model::WorldDescription& world) {
  const Eigen::Vector2d back = back_side(object, world);
  const Eigen::Vector2d along(std::abs(back.y()), std::abs(back.x()));  // the row's direction
  const double length = along.dot(object.size);
  const double depth = std::abs(back.dot(object.size));
  const int seats = std::max(1, static_cast<int>(std::lround(length / kSeatPitchM)));
  const double pitch = length / seats;
  const Eigen::Isometry3d X = object_frame(object);
  const Eigen::Vector3d along3(along.x(), along.y(), 0.0);
  const Eigen::Vector3d back3(back.x(), back.y(), 0.0);
  auto extent = [&](double along_m, double back_m, double z_m) {
    return Eigen::Vector3d(std::abs(along.x()) * along_m + std::abs(back.x()) * back_m,
                           std::abs(along.y()) * along_m + std::abs(back.y()) * back_m, z_m);
  };
  std::vector<RenderPrimitive> out;
  for (int k = 0; k < seats; ++k) {
    const Eigen::Vector3d centre = (-0.5 * length + (k + 0.5) * pitch) * along3;
    out.push_back(part(PrimitiveShape::kBox,
                       offset(X, centre + Eigen::Vector3d(0, 0, kChairSeatHeightM - 0.03)),
                       extent(pitch - 0.04, depth, 0.06), kFabricColour));
    for (const double a : {-1.0, 1.0}) {
      for (const double b : {-1.0, 1.0}) {
        const Eigen::Vector3d leg = centre + a * (0.5 * pitch - 0.05) * along3 +
                                    b * (0.5 * depth - 0.04) * back3 +
                                    Eigen::Vector3d(0, 0, 0.5 * (kChairSeatHeightM - 0.06));
        out.push_back(
            part(PrimitiveShape::kCylinder, offset(X, leg),
                 Eigen::Vector3d(2 * kLegRadiusM, 2 * kLegRadiusM, kChairSeatHeightM - 0.06),
                 kFrameColour));
      }
    }
  }
  const double back_height = std::max(height_m, kChairSeatHeightM + 0.3) - kChairSeatHeightM;
  out.push_back(part(PrimitiveShape::kBox,
                     offset(X, (0.5 * depth - 0.025) * back3 +
                                   Eigen::Vector3d(0, 0, kChairSeatHeightM + 0.5 * back_height)),
                     extent(length - 0.04, 0.05, back_height), kFabricColour));
  return out;
}

// A round (or square) table: top, pedestal and foot.
std::vector<RenderPrimitive> table(const model::StaticObject& object, double height_m) {
  const bool round = object.type == model::ShapeType::kCircle;
  const Eigen::Vector2d top =
      round ? Eigen::Vector2d::Constant(2.0 * object.radius_m) : object.size;
  const Eigen::Isometry3d X = object_frame(object);
  const PrimitiveShape shape = round ? PrimitiveShape::kCylinder : PrimitiveShape::kBox;
  return {part(shape, offset(X, {0, 0, height_m - 0.02}), {top.x(), top.y(), 0.04}, kTableTopColour,
               Surface::kWood),
          part(PrimitiveShape::kCylinder, offset(X, {0, 0, 0.5 * height_m}), {0.08, 0.08, height_m},
               kFrameColour),
          part(PrimitiveShape::kCylinder, offset(X, {0, 0, 0.015}),
               {0.6 * top.x(), 0.6 * top.y(), 0.03}, kFrameColour)};
}

// A pot and the foliage above it, about 1.2 m tall.
std::vector<RenderPrimitive> plant(const model::StaticObject& object) {
  const double r = object.radius_m;
  const Eigen::Isometry3d X = object_frame(object);
  return {
      part(PrimitiveShape::kCylinder, offset(X, {0, 0, 0.2}), {1.2 * r, 1.2 * r, 0.4}, kPotColour),
      part(PrimitiveShape::kSphere, offset(X, {0, 0, 0.8}), {2.0 * r, 2.0 * r, 0.9}, kLeafColour)};
}

// The cabinet and its bottle.
std::vector<RenderPrimitive> dispenser(const model::StaticObject& object, double height_m) {
  const Eigen::Isometry3d X = object_frame(object);
  const double body = std::max(height_m, 1.0);
  const double bottle = 0.6 * std::min(object.size.x(), object.size.y());
  return {part(PrimitiveShape::kBox, offset(X, {0, 0, 0.5 * body}),
               {object.size.x(), object.size.y(), body}, kDispenserColour),
          part(PrimitiveShape::kCylinder, offset(X, {0, 0, body + 0.2}), {bottle, bottle, 0.4},
               kBottleColour)};
}

// A reception counter: a work top at the object's height on the staff's side (the long side
// towards the nearest wall), a laminate front on a dark plinth, and on the visitors' side a raised
// transaction ledge at standing height (1.1 m).
std::vector<RenderPrimitive> reception_desk(const model::StaticObject& object, double height_m,
                                            const model::WorldDescription& world) {
  constexpr double kLedgeHeightM = 1.1, kLedgeDepthM = 0.3, kPlinthM = 0.1;
  const Eigen::Vector2d staff = staff_side(object, world);
  const Eigen::Vector2d along(std::abs(staff.y()), std::abs(staff.x()));
  const double length = along.dot(object.size), depth = std::abs(staff.dot(object.size));
  const auto extent = [&](double along_m, double across_m, double z_m) {
    return Eigen::Vector3d(along.x() * along_m + std::abs(staff.x()) * across_m,
                           along.y() * along_m + std::abs(staff.y()) * across_m, z_m);
  };
  const Eigen::Vector3d staff3(staff.x(), staff.y(), 0.0);
  const Eigen::Isometry3d X = object_frame(object);
  const double ledge = std::max(kLedgeHeightM, height_m + 0.1);
  const double visitors_side = -0.5 * depth + 0.5 * kLedgeDepthM;  // along staff3
  return {part(PrimitiveShape::kBox, offset(X, {0, 0, 0.5 * kPlinthM}),
               extent(length - 0.04, depth - 0.04, kPlinthM), kPlinthColour),
          part(PrimitiveShape::kBox, offset(X, {0, 0, 0.5 * (kPlinthM + height_m)}),
               extent(length, depth, height_m - kPlinthM), kPanelColour),
          part(PrimitiveShape::kBox, offset(X, Eigen::Vector3d(0, 0, height_m - 0.015)),
               extent(length, depth, 0.03), kTableTopColour, Surface::kWood),
          part(PrimitiveShape::kBox,
               offset(X, visitors_side * staff3 + Eigen::Vector3d(0, 0, 0.5 * (height_m + ledge))),
               extent(length, kLedgeDepthM, ledge - height_m), kPanelColour),
          part(PrimitiveShape::kBox,
               offset(X, visitors_side * staff3 + Eigen::Vector3d(0, 0, ledge + 0.015)),
               extent(length, kLedgeDepthM, 0.03), kTableTopColour, Surface::kWood)};
}

}  // namespace

std::optional<std::vector<RenderPrimitive>> furniture_of(const model::StaticObject& object,
                                                         double height_m,
                                                         const model::WorldDescription& world) {
  if (named(object, "chair") && object.type == model::ShapeType::kBox) {
    return chairs(object, height_m, world);
  }
  if (named(object, "table") && object.type != model::ShapeType::kPolygon) {
    return table(object, height_m);
  }
  if (named(object, "plant") && object.type == model::ShapeType::kCircle) {
    return plant(object);
  }
  if (named(object, "desk") && object.type == model::ShapeType::kBox) {
    return reception_desk(object, height_m, world);
  }
  if (named(object, "dispenser") && object.type == model::ShapeType::kBox) {
    return dispenser(object, height_m);
  }
  return std::nullopt;
}

}  // namespace ari_social_sim::rendering
