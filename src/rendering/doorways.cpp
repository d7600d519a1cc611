#include "ari_social_sim/rendering/doorways.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

namespace ari_social_sim::rendering {
namespace {

const Eigen::Vector3f kFrameColour{0.93f, 0.93f, 0.90f};  // painted wood
constexpr double kFrameWidthM = 0.06;
constexpr double kFrameProudM = 0.02;  // the frame stands out of each face of the wall
constexpr double kSameLineM = 0.02;
constexpr double kSameDirectionRad = 0.5 * M_PI / 180.0;

Eigen::Vector2d direction_of(const model::StaticObject& wall) {
  return {std::cos(wall.pose.theta), std::sin(wall.pose.theta)};
}

double height_of(const model::StaticObject& wall, double default_height_m) {
  return wall.height_m > 0.0 ? wall.height_m : default_height_m;
}

// The doorway between `a` and `b` when b continues a's line past a gap of a doorway's width.
std::optional<Doorway> doorway_between(const model::StaticObject& a, const model::StaticObject& b,
                                       double default_height_m) {
  const Eigen::Vector2d u = direction_of(a);
  const double turn = std::remainder(b.pose.theta - a.pose.theta, M_PI);
  const Eigen::Vector2d a_to_b = b.pose.position - a.pose.position;
  const double off_line = u.x() * a_to_b.y() - u.y() * a_to_b.x();
  if (std::abs(turn) > kSameDirectionRad || std::abs(off_line) > kSameLineM) {
    return std::nullopt;
  }
  // Along a's line from a's centre: a ends at half its length, b starts half its length before
  // its centre.
  const double a_end = 0.5 * a.size.x();
  const double b_start = u.dot(a_to_b) - 0.5 * b.size.x();
  const double width = b_start - a_end;
  if (width < kMinDoorwayWidthM || width > kMaxDoorwayWidthM) {
    return std::nullopt;
  }
  Doorway doorway;
  doorway.centre = a.pose.position + (a_end + 0.5 * width) * u;
  doorway.direction = u;
  doorway.width_m = width;
  doorway.wall_thickness_m = std::min(a.size.y(), b.size.y());
  doorway.wall_height_m = std::min(height_of(a, default_height_m), height_of(b, default_height_m));
  return doorway;
}

}  // namespace

std::vector<Doorway> doorways_of(const model::WorldDescription& world, double default_height_m) {
  std::vector<Doorway> doorways;
  for (const model::StaticObject& a : world.objects) {
    for (const model::StaticObject& b : world.objects) {
      if (&a != &b && a.type == model::ShapeType::kWall && b.type == model::ShapeType::kWall) {
        if (std::optional<Doorway> doorway = doorway_between(a, b, default_height_m)) {
          doorways.push_back(*doorway);
        }
      }
    }
  }
  return doorways;
}

std::vector<RenderPrimitive> doorway_primitives(const Doorway& doorway,
                                                const Eigen::Vector3f& wall_colour) {
  const double yaw = std::atan2(doorway.direction.y(), doorway.direction.x());
  const double frame_depth = doorway.wall_thickness_m + 2.0 * kFrameProudM;
  const auto at = [&](double along_m, double z_m) {
    return upright_pose(doorway.centre + along_m * doorway.direction, z_m, yaw);
  };
  std::vector<RenderPrimitive> out;
  const double above = doorway.wall_height_m - kDoorHeightM;
  if (above > 0.0) {
    out.push_back(solid(PrimitiveShape::kBox, at(0.0, kDoorHeightM + 0.5 * above),
                        {doorway.width_m, doorway.wall_thickness_m, above}, wall_colour,
                        Surface::kWall));
  }
  const double jamb_height = std::min(kDoorHeightM, doorway.wall_height_m);
  for (const double side : {-1.0, 1.0}) {
    out.push_back(solid(PrimitiveShape::kBox,
                        at(side * 0.5 * (doorway.width_m - kFrameWidthM), 0.5 * jamb_height),
                        {kFrameWidthM, frame_depth, jamb_height}, kFrameColour));
  }
  if (above > 0.0) {
    out.push_back(solid(PrimitiveShape::kBox, at(0.0, kDoorHeightM - 0.5 * kFrameWidthM),
                        {doorway.width_m, frame_depth, kFrameWidthM}, kFrameColour));
  }
  return out;
}

}  // namespace ari_social_sim::rendering
