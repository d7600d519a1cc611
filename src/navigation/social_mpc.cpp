#include "ari_social_sim/navigation/social_mpc.hpp"

#include <chrono>
#include <ctime>

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/navigation/initial_guess.hpp"

namespace ari_social_sim::navigation {

SocialMpc::SocialMpc(const MpcConfig& config, const FootprintModel& footprint)
    : config_(config),
      model_(config.step_s, footprint),
      cost_(config_, model_),
      bounds_(ControlBounds::of(config)),
      solver_(make_solver(config)) {}

namespace {

// CPU time of the calling thread (s): what a solve costs on one core, whatever else the machine
// runs at the same time.
double thread_cpu_s() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

MpcSolution SocialMpc::solve(const MpcProblem& problem) {
  ARI_CHECK(problem.sdf != nullptr && problem.geodesic != nullptr);
  const auto started = std::chrono::steady_clock::now();
  const double started_cpu_s = thread_cpu_s();
  cost_.set_problem(problem);
  cost_.reset_evaluations();

  // Score the start-point candidates; the solver refines the cheapest.
  constexpr double kSwerveRps = 0.8;
  std::vector<Eigen::VectorXd> candidates;
  if (has_previous_) {
    candidates.push_back(shift_by_one_step(previous_));
  }
  candidates.push_back(follow_geodesic(problem, config_, bounds_, 0.0));
  candidates.push_back(follow_geodesic(problem, config_, bounds_, kSwerveRps));
  candidates.push_back(follow_geodesic(problem, config_, bounds_, -kSwerveRps));
  candidates.emplace_back(Eigen::VectorXd::Zero(config_.control_count()));
  size_t best = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < candidates.size(); ++i) {
    candidates[i] = bounds_.clamp(candidates[i]);
    const double c = cost_.evaluate(candidates[i]);
    if (c < best_cost) {
      best_cost = c;
      best = i;
    }
  }

  MpcSolution solution;
  solution.controls = candidates[best];
  solution.cost = solver_->minimise(cost_, bounds_, solution.controls);
  solution.evaluations = cost_.evaluations();
  solution.terms = cost_.breakdown(solution.controls);
  solution.states = cost_.rollout().states;
  previous_ = solution.controls;
  has_previous_ = true;
  solution.solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  solution.solve_cpu_s = thread_cpu_s() - started_cpu_s;
  return solution;
}

}  // namespace ari_social_sim::navigation
