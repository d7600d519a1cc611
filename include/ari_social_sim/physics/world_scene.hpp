#pragma once

#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/physics/render_primitive.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::physics {

/// A person as the cameras see them: a body cylinder (elliptic: deeper than wide, turned with the
/// body), a head sphere and a face plate with two eyes on the side the head faces.
struct PersonFigure {
  double body_width_m{0.42};   // across the shoulders
  double body_depth_m{0.26};   // chest to back
  double body_height_m{1.45};  // floor to the base of the neck
  double head_diameter_m{0.22};
  double head_centre_height_m{1.6};
};

/// How the 2D world's flat shapes become solids. World files give outlines only, so heights are
/// chosen here: walls taller than anyone, furniture at table height.
struct SceneStyle {
  double wall_height_m{2.5};
  double furniture_height_m{0.75};
  PersonFigure person;
};

/// The floor (checkered), walls and furniture of a world, extruded upwards from z = 0.
std::vector<RenderPrimitive> static_primitives_of(const model::WorldDescription& world,
                                                  const SceneStyle& style);

/// Appends one person standing at `body` (map frame) with the head turned to face_direction_rad.
/// `shirt_index` picks the body colour so that neighbours look different.
void append_person(const core::Pose2& body, double face_direction_rad, size_t shirt_index,
                   const PersonFigure& shape, std::vector<RenderPrimitive>& out);

/// Appends every human of a ground-truth snapshot; the face turns with the gaze direction.
void append_people(const std::vector<world::HumanSnapshot>& humans, const SceneStyle& style,
                   std::vector<RenderPrimitive>& out);

}  // namespace ari_social_sim::physics
