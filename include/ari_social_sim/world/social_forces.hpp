#pragma once

#include <Eigen/Core>
#include <vector>

/// The force model of D6.4 §3.3.1 and §3.4.1 as plain functions of positions, so each
/// equation can be checked against hand-computed values. Positions are in the map frame (m).
/// Where D6.4's typesetting is garbled, the evident meaning is implemented (docs/world.md).
namespace ari_social_sim::world::social_forces {

using Vector2 = Eigen::Vector2d;
using Positions = std::vector<Eigen::Vector2d>;

/// Eq. 3.5: unit pull toward the goal, scaled down linearly inside `goal_distance_m` (Delta_G).
Vector2 goal_force(const Vector2& p, const Vector2& goal, double goal_distance_m);

/// Eq. 3.6-3.7: f = -(Delta_p - d_min)^2 R / |R| with R = sum of (p_i - p) over the agents inside
/// the personal area (distance < Delta_p) and d_min the distance to the closest of them.
/// `others` may contain agents outside the area; they are ignored. Zero if none is inside.
Vector2 repulsion_force(const Vector2& p, const Positions& others, double personal_distance_m);

/// Eq. 3.2 with the evident sign: the rotation that turns the agent toward its movement direction
/// while farther than Delta_G from the goal, and toward the goal orientation once within it.
/// Returns wrap(theta_target - theta) in [-pi, pi).
double navigation_rotation(double theta, double theta_move, double theta_goal,
                           double distance_to_goal_m, double goal_distance_m);

/// Eq. 3.13: centre of the agent and the group members inside its social space.
Vector2 local_group_centre(const Vector2& p, const Positions& social_neighbours);

/// Eq. 3.14 (evident meaning of the garbled formula): mean distance of the agent and its social
/// neighbours to the centre c, m = (|p - c| + sum |p_i - c|) / (N_s + 1).
double mean_distance_to_centre(const Vector2& p, const Positions& social_neighbours,
                               const Vector2& c);

/// Eq. 3.15: f = (1 - m / |c - p|) (c - p); attracts the agent to, or repels it from, the local
/// centre until its distance equals the mean distance. Zero without neighbours or at c.
Vector2 equality_force(const Vector2& p, const Positions& social_neighbours);

/// Eq. 3.16: orientation vector sum (p_i - p) over the social neighbours.
Vector2 equality_orientation(const Vector2& p, const Positions& social_neighbours);

/// Eq. 3.17: f = alpha (1 - s / |o - p|) (o - p), alpha = N_a / (N_s + 1); pulls the agent onto
/// the o-space circle of radius s around o. Zero at o.
Vector2 cohesion_force(const Vector2& p, const Vector2& o, double ospace_radius_m, int group_size,
                       int social_neighbour_count);

/// Eq. 3.18: orientation vector sum (p_i - p) over all members of the group.
Vector2 cohesion_orientation(const Vector2& p, const Positions& members);

}  // namespace ari_social_sim::world::social_forces
