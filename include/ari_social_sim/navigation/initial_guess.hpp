#pragma once

#include <Eigen/Core>

#include "ari_social_sim/navigation/mpc_problem.hpp"
#include "ari_social_sim/navigation/mpc_solver.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"

namespace ari_social_sim::navigation {

/// A control sequence that follows the geodesic field downhill, as a start point for the solvers:
/// steer toward -grad G (straight at the goal point within 0.5 m; on the spot to the goal heading
/// once MpcProblem::at_goal_position), slow down as the heading error grows
/// and near the goal, change speed within ARI's acceleration limits, turn the head toward the
/// look-at point. `turn_bias_rps` adds a constant turn
/// over the first half of the horizon (a swerve left or right around someone ahead).
Eigen::VectorXd follow_geodesic(const MpcProblem& problem, const MpcConfig& config,
                                const ControlBounds& bounds, double turn_bias_rps);

/// `previous` advanced by one step: its first step dropped, its last repeated.
Eigen::VectorXd shift_by_one_step(const Eigen::VectorXd& previous);

}  // namespace ari_social_sim::navigation
