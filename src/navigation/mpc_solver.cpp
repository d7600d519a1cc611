#include "ari_social_sim/navigation/mpc_solver.hpp"

#include "ari_social_sim/navigation/mppi_solver.hpp"
#include "ari_social_sim/navigation/nlopt_solver.hpp"

namespace ari_social_sim::navigation {

ControlBounds ControlBounds::of(const MpcConfig& config) {
  ControlBounds bounds;
  const int n = config.control_count();
  bounds.lower.resize(n);
  bounds.upper.resize(n);
  for (int t = 0; t < config.horizon_steps; ++t) {
    bounds.lower.segment<3>(3 * t) << config.min_linear_mps, -config.max_angular_rps,
        -config.limits.head_pan_max_speed_rps;
    bounds.upper.segment<3>(3 * t) << config.max_linear_mps, config.max_angular_rps,
        config.limits.head_pan_max_speed_rps;
  }
  return bounds;
}

std::unique_ptr<MpcSolver> make_solver(const MpcConfig& config) {
  if (config.solver == SolverKind::kMppi) {
    return std::make_unique<MppiSolver>(config);
  }
  return std::make_unique<NloptSolver>(config.solver, config.control_count(),
                                       config.max_evaluations);
}

}  // namespace ari_social_sim::navigation
