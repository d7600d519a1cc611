#pragma once

#include <optional>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// m; the top of a chair's seat (a waiting-room chair's), where a seated figure rests.
constexpr double kChairSeatHeightM = 0.45;

/// A world object drawn as the furniture its name says it is, within the footprint and height the
/// physics collides with: a chair (or a row of chairs, one seat per half metre) with legs, a seat
/// and a backrest on the side facing the nearest wall or furniture; a table with a top, a pedestal
/// and a foot; a plant in a pot; a water dispenser with its bottle. Nothing for other objects,
/// which stay solid blocks (a reception desk is one).
std::optional<std::vector<RenderPrimitive>> furniture_of(const model::StaticObject& object,
                                                         double height_m,
                                                         const model::WorldDescription& world);

}  // namespace ari_social_sim::rendering
