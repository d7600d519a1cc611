#pragma once

#include <vector>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// A closed door's leaf: a common single door (0.9 m) as high as an opening (kDoorHeightM).
constexpr double kDoorLeafWidthM = 0.9;
/// Floor kept clear in front of a closed door, on each side: room to open it and walk through.
constexpr double kDoorClearanceM = 0.8;
/// Where pictures and notice boards hang: their centres at a standing adult's eye height.
constexpr double kHangingCentreM = 1.5;

/// What a building's walls carry that a world file, which gives outlines for the physics, does
/// not: a closed door through the wall every few slots of two metres, on every other wall (in the
/// file's order), and framed pictures and notice boards at eye height in the other slots, on the
/// faces that look into the world. Each keeps 0.4 m from its wall's ends (corners, doorways) and
/// clear of `furniture` (the world's other solids, as drawn): a door needs kDoorClearanceM of free
/// floor on both sides, a picture 0.3 m in front of it at its height, so pictures hang over low
/// chairs but not behind a plant. The physics knows none of them: a closed door is wall to it, and
/// the rest stand at most 3 cm proud of the wall.
std::vector<RenderPrimitive> wall_fittings_of(const model::WorldDescription& world,
                                              double default_wall_height_m,
                                              const std::vector<RenderPrimitive>& furniture);

}  // namespace ari_social_sim::rendering
