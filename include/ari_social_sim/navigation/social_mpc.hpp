#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "ari_social_sim/navigation/mpc_problem.hpp"
#include "ari_social_sim/navigation/mpc_solver.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/trajectory_cost.hpp"

namespace ari_social_sim::navigation {

/// What one MPC solve found.
struct MpcSolution {
  Eigen::VectorXd controls;        // 3 N: the first step is the command to apply now
  std::vector<RobotState> states;  // predicted states 0..N under those controls
  double cost{0.0};
  std::vector<TermCost> terms;  // each term's share of the cost
  int evaluations{0};           // cost evaluations, start-point candidates included
  double solve_time_s{0.0};     // wall time of solve()
  double solve_cpu_s{0.0};      // CPU time of solve() on its thread (one core)

  double linear_mps() const { return controls[0]; }
  double angular_rps() const { return controls[1]; }
  /// Head pan (rad) the plan reaches at its first step: the target to command now.
  double pan_target() const { return states.size() > 1 ? states[1].pan : 0.0; }
};

/// SocialMPC (D6.4 §3.5.5; docs/navigation.md): minimises the sum of the cost terms over a
/// horizon of N steps of the unicycle-plus-pan model within ARI's limits, warm-started from the
/// previous solution shifted by one step. Several start points are scored (the shifted previous
/// solution, a geodesic follower going straight and swerving either way, standing still) and the
/// solver starts from the cheapest, which keeps the gradient solvers out of the local minimum
/// right in front of a person.
class SocialMpc {
 public:
  SocialMpc(const MpcConfig& config, const FootprintModel& footprint);
  // The cost holds a reference to the model member: neither copyable nor movable.
  SocialMpc(const SocialMpc&) = delete;
  SocialMpc& operator=(const SocialMpc&) = delete;

  /// Plans from `problem` (its fields must be set). Never throws.
  MpcSolution solve(const MpcProblem& problem);
  /// Forgets the warm start (new goal).
  void reset() { has_previous_ = false; }

  const MpcConfig& config() const { return config_; }
  const UnicycleModel& model() const { return model_; }

 private:
  MpcConfig config_;
  UnicycleModel model_;
  TrajectoryCost cost_;
  ControlBounds bounds_;
  std::unique_ptr<MpcSolver> solver_;
  Eigen::VectorXd previous_;
  bool has_previous_{false};
};

}  // namespace ari_social_sim::navigation
