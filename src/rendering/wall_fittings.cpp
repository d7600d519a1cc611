#include "ari_social_sim/rendering/wall_fittings.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "ari_social_sim/rendering/doorways.hpp"

namespace ari_social_sim::rendering {
namespace {

constexpr double kSlotM = 2.0;          // wall length given to each fitting
constexpr double kEndMarginM = 0.4;     // kept free at a wall's ends: corners, doorways' frames
constexpr double kShortestSlotM = 1.3;  // what a notice board and its margins need
constexpr int kSlotsPerDoor = 3;        // on a wall with doors, one slot in three
constexpr double kHangingClearanceM = 0.3;
constexpr double kBesideM = 0.1;       // furniture this close beside a fitting is in its way too
constexpr double kFrameWidthM = 0.06;  // a door's painted frame, as a doorway's
constexpr double kFrameProudM = 0.03;
constexpr double kLeafProudM = 0.02;
constexpr double kHandleProudM = 0.07;  // a lever handle
constexpr double kHandleHeightM = 1.0;
constexpr double kHangingProudM = 0.02;
constexpr double kLayerM = 0.004;  // between a picture's frame, mat and print: apart in depth
constexpr double kPictureWidthM = 0.8;
constexpr double kPictureHeightM = 0.6;
constexpr double kBoardWidthM = 1.2;
constexpr double kBoardHeightM = 0.9;
constexpr double kHangingTopM = kHangingCentreM + 0.5 * kBoardHeightM;

// A closed door's leaf: its colour and surface.
struct Finish {
  Eigen::Vector3f colour;
  Surface surface;
};

const Eigen::Vector3f kDoorFrameColour{0.93f, 0.93f, 0.90f};  // painted wood, as doorways'
// Oak and walnut veneer, and a leaf painted blue-grey: hospital and office doors.
const std::array<Finish, 3> kLeafFinishes{{{{0.30f, 0.20f, 0.13f}, Surface::kWood},
                                           {{0.14f, 0.09f, 0.05f}, Surface::kWood},
                                           {{0.25f, 0.32f, 0.40f}, Surface::kMatte}}};
const Eigen::Vector3f kHandleColour{0.55f, 0.55f, 0.56f};  // brushed steel
const Eigen::Vector3f kPictureFrameColour{0.04f, 0.04f, 0.04f};
const Eigen::Vector3f kMatColour{0.85f, 0.84f, 0.80f};
// Prints, as their upper and lower halves: sky over a dark sea, sky over green hills, an abstract
// in rust and brown, a night sky over sand.
const std::array<std::array<Eigen::Vector3f, 2>, 4> kPrints{
    {{{{0.35f, 0.50f, 0.65f}, {0.06f, 0.14f, 0.22f}}},
     {{{0.55f, 0.65f, 0.75f}, {0.10f, 0.22f, 0.07f}}},
     {{{0.55f, 0.25f, 0.08f}, {0.18f, 0.08f, 0.04f}}},
     {{{0.05f, 0.06f, 0.12f}, {0.50f, 0.42f, 0.28f}}}}};
const Eigen::Vector3f kBoardFrameColour{0.60f, 0.61f, 0.62f};  // anodised aluminium
const Eigen::Vector3f kCorkColour{0.40f, 0.25f, 0.13f};
const std::array<Eigen::Vector3f, 3> kPaperColours{
    {{0.90f, 0.90f, 0.88f}, {0.92f, 0.88f, 0.55f}, {0.70f, 0.82f, 0.92f}}};
// Notices pinned on a board, A4 upright: their centres from the board's, m.
const std::array<Eigen::Vector2d, 5> kNoticeOffsets{
    {{-0.38, 0.17}, {-0.08, 0.13}, {0.26, 0.19}, {-0.24, -0.20}, {0.20, -0.17}}};
constexpr double kNoticeWidthM = 0.21;
constexpr double kNoticeHeightM = 0.297;

// One wall seen from one of its faces: `across` points out of that face.
struct WallFace {
  Eigen::Vector2d centre;  // of the wall, on its centre line
  Eigen::Vector2d along;
  Eigen::Vector2d across;
  double yaw;  // of `along`
  double half_thickness;
};

WallFace face_of(const model::StaticObject& wall, double side) {
  const Eigen::Vector2d along(std::cos(wall.pose.theta), std::sin(wall.pose.theta));
  return {wall.pose.position, along, side * Eigen::Vector2d(-along.y(), along.x()), wall.pose.theta,
          0.5 * wall.size.y()};
}

// A box on the face, `along_m` from the wall's centre and its centre `z_m` high, standing `proud_m`
// out of the face.
RenderPrimitive panel(const WallFace& face, double along_m, double z_m, double width_m,
                      double height_m, double proud_m, const Eigen::Vector3f& colour) {
  const Eigen::Vector2d xy =
      face.centre + along_m * face.along + (face.half_thickness + 0.5 * proud_m) * face.across;
  return solid(PrimitiveShape::kBox, upright_pose(xy, z_m, face.yaw), {width_m, proud_m, height_m},
               colour);
}

// A box through the wall at `along_m`, standing `proud_m` out of both faces.
RenderPrimitive through(const WallFace& face, double along_m, double z_m, double width_m,
                        double height_m, double proud_m, const Finish& finish) {
  return solid(
      PrimitiveShape::kBox, upright_pose(face.centre + along_m * face.along, z_m, face.yaw),
      {width_m, 2.0 * (face.half_thickness + proud_m), height_m}, finish.colour, finish.surface);
}

// The space in front of a face that a fitting needs free: `width_m` about `along_m`, `depth_m`
// out of the face, from `bottom_m` to `top_m` above the floor.
struct Space {
  double along_m, width_m, depth_m, bottom_m, top_m;
};

// Whether a solid may reach into `space`: its footprint taken as the circle round its corners.
bool reaches_into(const RenderPrimitive& solid, const WallFace& face, const Space& space) {
  const Eigen::Vector3d centre = solid.X_world_shape.translation();
  if (centre.z() + 0.5 * solid.size.z() <= space.bottom_m ||
      centre.z() - 0.5 * solid.size.z() >= space.top_m) {
    return false;
  }
  double radius = 0.5 * solid.size.head<2>().norm();
  if (!solid.outline.empty()) {
    radius = 0.0;
    for (const Eigen::Vector2d& point : solid.outline)
      radius = std::max(radius, point.norm());
  }
  const Eigen::Vector2d offset = centre.head<2>() - face.centre;
  const double along = offset.dot(face.along) - space.along_m;
  const double out = offset.dot(face.across) - face.half_thickness;
  return std::abs(along) < 0.5 * space.width_m + kBesideM + radius && out > -radius &&
         out < space.depth_m + radius;
}

bool free_of(const std::vector<RenderPrimitive>& furniture, const WallFace& face,
             const Space& space) {
  return std::none_of(furniture.begin(), furniture.end(), [&](const RenderPrimitive& solid) {
    return reaches_into(solid, face, space);
  });
}

bool inside_wall(const model::StaticObject& wall, const Eigen::Vector2d& point) {
  const Eigen::Vector2d local = Eigen::Rotation2Dd(-wall.pose.theta) * (point - wall.pose.position);
  return std::abs(local.x()) <= 0.5 * wall.size.x() && std::abs(local.y()) <= 0.5 * wall.size.y();
}

// Whether a face looks into the world at `along_m`: the floor half a metre out from it is the
// world's and in no wall. The outer faces of a building's walls do not.
bool looks_into_world(const model::WorldDescription& world, const WallFace& face, double along_m) {
  const Eigen::Vector2d out =
      face.centre + along_m * face.along + (face.half_thickness + 0.5) * face.across;
  return world.contains(out) &&
         std::none_of(world.objects.begin(), world.objects.end(), [&](const auto& object) {
           return object.type == model::ShapeType::kWall && inside_wall(object, out);
         });
}

// Slot centres along a wall `length_m` long, from its centre: one per kSlotM of what its ends
// leave, none when that is too short for a notice board.
std::vector<double> slots_of(double length_m) {
  const double usable = length_m - 2.0 * kEndMarginM;
  if (usable < kShortestSlotM)
    return {};
  const int count = std::max(1, static_cast<int>(usable / kSlotM));
  std::vector<double> slots;
  for (int i = 0; i < count; ++i)
    slots.push_back(-0.5 * usable + (i + 0.5) * usable / count);
  return slots;
}

bool is_door_slot(size_t slot, size_t slot_count) {
  return slot % kSlotsPerDoor == (slot_count > 1 ? 1u : 0u);
}

// A closed door through the wall: its leaf, a painted frame round it and a lever handle, all seen
// from both faces.
std::vector<RenderPrimitive> door(const WallFace& face, double along_m, const Finish& leaf) {
  const Finish frame{kDoorFrameColour, Surface::kMatte};
  const double jamb = 0.5 * (kDoorLeafWidthM + kFrameWidthM);
  const double frame_height = kDoorHeightM + kFrameWidthM;
  return {
      through(face, along_m, 0.5 * kDoorHeightM, kDoorLeafWidthM, kDoorHeightM, kLeafProudM, leaf),
      through(face, along_m - jamb, 0.5 * frame_height, kFrameWidthM, frame_height, kFrameProudM,
              frame),
      through(face, along_m + jamb, 0.5 * frame_height, kFrameWidthM, frame_height, kFrameProudM,
              frame),
      through(face, along_m, kDoorHeightM + 0.5 * kFrameWidthM,
              kDoorLeafWidthM + 2.0 * kFrameWidthM, kFrameWidthM, kFrameProudM, frame),
      through(face, along_m + 0.5 * kDoorLeafWidthM - 0.12, kHandleHeightM, 0.14, 0.025,
              kHandleProudM, {kHandleColour, Surface::kMatte})};
}

// Whether a door fits at `along_m`: the floor in front of it clear on both faces, and at least
// one of them looking into the world.
bool door_fits(const model::WorldDescription& world, const std::vector<RenderPrimitive>& furniture,
               const model::StaticObject& wall, double along_m) {
  const Space space{along_m, kDoorLeafWidthM + 2.0 * kFrameWidthM, kDoorClearanceM, 0.0,
                    kDoorHeightM};
  bool into_world = false;
  for (const double side : {-1.0, 1.0}) {
    const WallFace face = face_of(wall, side);
    if (!free_of(furniture, face, space))
      return false;
    into_world = into_world || looks_into_world(world, face, along_m);
  }
  return into_world;
}

// A framed print behind a pale mat.
std::vector<RenderPrimitive> picture(const WallFace& face, double along_m,
                                     const std::array<Eigen::Vector3f, 2>& print) {
  constexpr double kFrameM = 0.025, kMatM = 0.07;
  const double print_width = kPictureWidthM - 2.0 * (kFrameM + kMatM);
  const double half_height = 0.5 * (kPictureHeightM - 2.0 * (kFrameM + kMatM));
  const double z = kHangingCentreM;
  return {
      panel(face, along_m, z, kPictureWidthM, kPictureHeightM, kHangingProudM, kPictureFrameColour),
      panel(face, along_m, z, kPictureWidthM - 2.0 * kFrameM, kPictureHeightM - 2.0 * kFrameM,
            kHangingProudM + kLayerM, kMatColour),
      panel(face, along_m, z + 0.5 * half_height, print_width, half_height,
            kHangingProudM + 2.0 * kLayerM, print[0]),
      panel(face, along_m, z - 0.5 * half_height, print_width, half_height,
            kHangingProudM + 2.0 * kLayerM, print[1])};
}

// A cork board in an aluminium frame with notices pinned on it, their paper colours from
// `first_paper` on.
std::vector<RenderPrimitive> notice_board(const WallFace& face, double along_m,
                                          size_t first_paper) {
  constexpr double kFrameM = 0.02;
  const double z = kHangingCentreM;
  std::vector<RenderPrimitive> parts{
      panel(face, along_m, z, kBoardWidthM, kBoardHeightM, kHangingProudM, kBoardFrameColour),
      panel(face, along_m, z, kBoardWidthM - 2.0 * kFrameM, kBoardHeightM - 2.0 * kFrameM,
            kHangingProudM + kLayerM, kCorkColour)};
  for (size_t i = 0; i < kNoticeOffsets.size(); ++i) {
    parts.push_back(panel(face, along_m + kNoticeOffsets[i].x(), z + kNoticeOffsets[i].y(),
                          kNoticeWidthM, kNoticeHeightM, kHangingProudM + 2.0 * kLayerM,
                          kPaperColours[(first_paper + i) % kPaperColours.size()]));
  }
  return parts;
}

// Pictures and notice boards in turn (two pictures to a board), each face's from where the last
// left off.
class Hangings {
 public:
  std::vector<RenderPrimitive> next(const WallFace& face, double along_m) {
    const size_t n = count_++;
    if (n % 3 == 1)
      return notice_board(face, along_m, n);
    return picture(face, along_m, kPrints[n % kPrints.size()]);
  }

 private:
  size_t count_{0};
};

void append(std::vector<RenderPrimitive>& out, const std::vector<RenderPrimitive>& parts) {
  out.insert(out.end(), parts.begin(), parts.end());
}

}  // namespace

std::vector<RenderPrimitive> wall_fittings_of(const model::WorldDescription& world,
                                              double default_wall_height_m,
                                              const std::vector<RenderPrimitive>& furniture) {
  std::vector<RenderPrimitive> out;
  Hangings hangings;
  size_t walls = 0, doors = 0;
  const Space hanging{0.0, kBoardWidthM, kHangingClearanceM, kHangingCentreM - 0.5 * kBoardHeightM,
                      kHangingTopM};
  for (const model::StaticObject& wall : world.objects) {
    if (wall.type != model::ShapeType::kWall)
      continue;
    const double height = wall.height_m > 0.0 ? wall.height_m : default_wall_height_m;
    const bool has_doors = walls++ % 2 == 0 && height >= kDoorHeightM + kFrameWidthM;
    const std::vector<double> slots = slots_of(wall.size.x());
    for (size_t i = 0; i < slots.size(); ++i) {
      if (has_doors && is_door_slot(i, slots.size()) &&
          door_fits(world, furniture, wall, slots[i])) {
        append(out,
               door(face_of(wall, 1.0), slots[i], kLeafFinishes[doors++ % kLeafFinishes.size()]));
        continue;
      }
      if (height < kHangingTopM)
        continue;
      for (const double side : {-1.0, 1.0}) {
        const WallFace face = face_of(wall, side);
        Space space = hanging;
        space.along_m = slots[i];
        if (looks_into_world(world, face, slots[i]) && free_of(furniture, face, space)) {
          append(out, hangings.next(face, slots[i]));
        }
      }
    }
  }
  return out;
}

}  // namespace ari_social_sim::rendering
