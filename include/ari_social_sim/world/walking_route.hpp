#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::world {

/// Cell size (m) of the grid walking routes are planned on: a tenth of a shoulder width, fine
/// enough for a 1 m door to leave a passable band several cells wide.
constexpr double kRouteCellM = 0.1;

/// A walkable route from a start to a goal around the world's walls and furniture, planned once
/// on a coarse occupancy grid (Dijkstra over 8-connected cells that keep `clearance_m` from any
/// wall, furniture or the floor's edge; cells with little clearance cost more, so the route keeps
/// to the middle of doors and corridors), then smoothed. It knows the clearance along itself, so
/// a walking group sees where the way narrows. Agents are not obstacles: people avoid each other
/// with social forces while following it.
class WalkingRoute {
 public:
  /// The route, or nullopt when no cell near the goal is reachable from one near the start
  /// (start and goal snap to the nearest passable cell within 0.5 m). Positions in the map frame.
  static std::optional<WalkingRoute> plan(const model::WorldDescription& world,
                                          const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                                          double clearance_m);

  /// m along the route from the start to the goal.
  double length_m() const { return arc_m_.back(); }
  /// The point `s_m` along the route, clamped to [0, length].
  Eigen::Vector2d point_at(double s_m) const;
  /// Walking direction (rad, map frame) at `s_m`: along the chord over +-1 m, which
  /// smooths the grid's steps.
  double heading_at(double s_m) const;
  /// Least clearance (m) to walls, furniture and the floor's edge on the route between s0 and s1.
  double min_clearance_m(double s0_m, double s1_m) const;
  const std::vector<Eigen::Vector2d>& points() const { return points_; }

 private:
  std::vector<Eigen::Vector2d> points_;
  std::vector<double> arc_m_;        // arc length at each point
  std::vector<double> clearance_m_;  // at each point
};

}  // namespace ari_social_sim::world
