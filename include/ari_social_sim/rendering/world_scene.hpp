#pragma once

#include <vector>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// How the 2D world's flat shapes become solids. World files give outlines only, so heights are
/// chosen here: walls taller than anyone, furniture at table height.
struct SceneStyle {
  double wall_height_m{2.5};
  double furniture_height_m{0.75};
};

/// The floor (checkered), walls and furniture of a world, extruded upwards from z = 0.
std::vector<RenderPrimitive> static_primitives_of(const model::WorldDescription& world,
                                                  const SceneStyle& style);

}  // namespace ari_social_sim::rendering
