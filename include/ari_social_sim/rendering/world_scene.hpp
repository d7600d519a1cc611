#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// How the 2D world's flat shapes become solids. World files give outlines only, so heights are
/// chosen here: walls taller than anyone, furniture at table height.
struct SceneStyle {
  double wall_height_m{2.5};
  double furniture_height_m{0.75};
  bool ceiling{true};          // over a world with walls: its rooms are indoors
  double lamp_spacing_m{3.0};  // ceiling lamps on a square grid
  Eigen::Vector2d lamp_size_m{0.6, 1.2};
};

/// The floor (tiled), walls, furniture of a world, extruded upwards from z = 0, and over a world
/// with walls a ceiling at the walls' top with lamps.
std::vector<RenderPrimitive> static_primitives_of(const model::WorldDescription& world,
                                                  const SceneStyle& style);

}  // namespace ari_social_sim::rendering
