#include "ari_social_sim/world/social_forces.hpp"

#include <cmath>
#include <limits>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::world::social_forces {
namespace {
// Below this distance (m) a direction is undefined and the force it would scale is taken as 0.
constexpr double kEpsilon = 1e-9;
}  // namespace

Vector2 goal_force(const Vector2& p, const Vector2& goal, double goal_distance_m) {
  const Vector2 to_goal = goal - p;
  const double distance = to_goal.norm();
  if (distance < kEpsilon) {
    return Vector2::Zero();
  }
  return std::min(1.0, distance / goal_distance_m) * to_goal / distance;
}

Vector2 repulsion_force(const Vector2& p, const Positions& others, double personal_distance_m) {
  Vector2 r_sum = Vector2::Zero();
  double d_min = std::numeric_limits<double>::infinity();
  for (const Vector2& other : others) {
    const double d = (other - p).norm();
    if (d < personal_distance_m) {
      r_sum += other - p;
      d_min = std::min(d_min, d);
    }
  }
  const double r_norm = r_sum.norm();
  if (!std::isfinite(d_min) || r_norm < kEpsilon) {
    return Vector2::Zero();
  }
  const double depth = personal_distance_m - d_min;
  return -depth * depth * r_sum / r_norm;
}

double navigation_rotation(double theta, double theta_move, double theta_goal,
                           double distance_to_goal_m, double goal_distance_m) {
  const double target = distance_to_goal_m > goal_distance_m ? theta_move : theta_goal;
  return core::angle_difference(target, theta);
}

Vector2 local_group_centre(const Vector2& p, const Positions& social_neighbours) {
  Vector2 sum = p;
  for (const Vector2& q : social_neighbours) {
    sum += q;
  }
  return sum / static_cast<double>(social_neighbours.size() + 1);
}

double mean_distance_to_centre(const Vector2& p, const Positions& social_neighbours,
                               const Vector2& c) {
  double sum = (p - c).norm();
  for (const Vector2& q : social_neighbours) {
    sum += (q - c).norm();
  }
  return sum / static_cast<double>(social_neighbours.size() + 1);
}

Vector2 equality_force(const Vector2& p, const Positions& social_neighbours) {
  if (social_neighbours.empty()) {
    return Vector2::Zero();
  }
  const Vector2 c = local_group_centre(p, social_neighbours);
  const double distance = (c - p).norm();
  if (distance < kEpsilon) {
    return Vector2::Zero();
  }
  const double m = mean_distance_to_centre(p, social_neighbours, c);
  return (1.0 - m / distance) * (c - p);
}

Vector2 equality_orientation(const Vector2& p, const Positions& social_neighbours) {
  Vector2 sum = Vector2::Zero();
  for (const Vector2& q : social_neighbours) {
    sum += q - p;
  }
  return sum;
}

Vector2 cohesion_force(const Vector2& p, const Vector2& o, double ospace_radius_m, int group_size,
                       int social_neighbour_count) {
  const double distance = (o - p).norm();
  if (distance < kEpsilon) {
    return Vector2::Zero();
  }
  const double alpha =
      static_cast<double>(group_size) / static_cast<double>(social_neighbour_count + 1);
  return alpha * (1.0 - ospace_radius_m / distance) * (o - p);
}

Vector2 cohesion_orientation(const Vector2& p, const Positions& members) {
  return equality_orientation(p, members);
}

}  // namespace ari_social_sim::world::social_forces
