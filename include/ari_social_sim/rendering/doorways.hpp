#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// A gap between two walls on one line that people walk through: world files draw a doorway as
/// two walls with a gap between them, open from the floor to the walls' top.
struct Doorway {
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};      // on the walls' centre line
  Eigen::Vector2d direction{Eigen::Vector2d::UnitX()};  // along the walls, unit
  double width_m{0.0};
  double wall_thickness_m{0.0};
  double wall_height_m{0.0};  // the lower of the two walls
};

/// Door openings as building codes size them: 0.6 to 2.5 m wide (single to double doors, the
/// European minimum clear width for wheelchairs being 0.8 to 0.9 m), 2.1 m high.
constexpr double kMinDoorwayWidthM = 0.6;
constexpr double kMaxDoorwayWidthM = 2.5;
constexpr double kDoorHeightM = 2.1;

/// Every doorway of the world: pairs of walls whose centre lines coincide (within 2 cm and half a
/// degree) with a gap between their ends of kMinDoorwayWidthM to kMaxDoorwayWidthM.
std::vector<Doorway> doorways_of(const model::WorldDescription& world, double default_height_m);

/// A doorway's solids: the wall above it (from kDoorHeightM to the walls' top, in the walls'
/// colour and surface) and a painted frame, two jambs and a head, standing 2 cm proud of each
/// face of the wall.
std::vector<RenderPrimitive> doorway_primitives(const Doorway& doorway,
                                                const Eigen::Vector3f& wall_colour);

}  // namespace ari_social_sim::rendering
