#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/rendering/render_mesh.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"

namespace ari_social_sim::rendering {

/// A static thing's footprint on the floor plan and the height of its underside: what shades
/// the floor under and around it.
struct FloorOccluder {
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
  Eigen::Vector2d x_axis{Eigen::Vector2d::UnitX()};    // the footprint's own x, a unit vector
  Eigen::Vector2d half_size{Eigen::Vector2d::Zero()};  // m; for a round one, its radii
  bool round{false};
  double underside_m{0.0};  // 0 for what stands on the floor

  /// Distance (m) from `point` to the footprint, 0 inside it.
  double distance_to(const Eigen::Vector2d& point) const;
};

/// The room's furniture that shades the floor: every primitive but floors, walls, ceilings and
/// lamps whose underside is lower than a table's ledge and that is wider than a chair's leg
/// (whose shade is smaller than the floor's lit facets).
std::vector<FloorOccluder> floor_occluders_of(const std::vector<RenderPrimitive>& primitives);

/// The share (0.3-1) of the room's light that reaches the floor at `point` past `occluders`
/// (ambient occlusion): the ceiling's lamps light the floor from above, so a seat or a table top
/// takes the floor beneath it into its shade, about as much as the share of the sky over that
/// point it covers (R^2 / (R^2 + h^2) for a disc of radius R at height h, doubled for the direct
/// light), fading over half its height around it; what stands on the floor darkens a rim around
/// its foot.
double floor_openness(const std::vector<FloorOccluder>& occluders, const Eigen::Vector2d& point);

/// Darkens each vertex of `floor` by its floor_openness, as the lighting would (linear light,
/// display gamma 2.2). The floor's vertices are static and lit once, so the shade costs nothing
/// per frame.
void shade_floor(const std::vector<FloorOccluder>& occluders, RenderMesh& floor);

}  // namespace ari_social_sim::rendering
