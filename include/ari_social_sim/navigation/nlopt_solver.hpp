#pragma once

#include "ari_social_sim/navigation/mpc_solver.hpp"

struct nlopt_opt_s;

namespace ari_social_sim::navigation {

/// Gradient-based minimisation with NLopt (Debian's libnlopt): L-BFGS with bounds (Luksan's
/// low-storage BFGS) or SLSQP, on the analytic gradient of TrajectoryCost, stopped after
/// `max_evaluations` evaluations or a relative change below 1e-6.
class NloptSolver : public MpcSolver {
 public:
  NloptSolver(SolverKind kind, int control_count, int max_evaluations);
  ~NloptSolver() override;
  NloptSolver(const NloptSolver&) = delete;
  NloptSolver& operator=(const NloptSolver&) = delete;

  double minimise(TrajectoryCost& cost, const ControlBounds& bounds,
                  Eigen::VectorXd& controls) override;

 private:
  nlopt_opt_s* optimiser_;
};

}  // namespace ari_social_sim::navigation
