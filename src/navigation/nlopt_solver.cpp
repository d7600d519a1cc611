#include "ari_social_sim/navigation/nlopt_solver.hpp"

#include <nlopt.h>

#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::navigation {
namespace {

struct Objective {
  TrajectoryCost* cost;
  Eigen::VectorXd controls;
  Eigen::VectorXd gradient;
};

double objective(unsigned n, const double* x, double* grad, void* data) {
  auto* o = static_cast<Objective*>(data);
  o->controls = Eigen::Map<const Eigen::VectorXd>(x, n);
  const double value = o->cost->evaluate(o->controls, grad != nullptr ? &o->gradient : nullptr);
  if (grad != nullptr) {
    Eigen::Map<Eigen::VectorXd>(grad, n) = o->gradient;
  }
  return value;
}

}  // namespace

NloptSolver::NloptSolver(SolverKind kind, int control_count, int max_evaluations) {
  ARI_CHECK(kind == SolverKind::kLbfgs || kind == SolverKind::kSlsqp);
  optimiser_ = nlopt_create(kind == SolverKind::kLbfgs ? NLOPT_LD_LBFGS : NLOPT_LD_SLSQP,
                            static_cast<unsigned>(control_count));
  ARI_CHECK(optimiser_ != nullptr);
  nlopt_set_maxeval(optimiser_, max_evaluations);
  nlopt_set_ftol_rel(optimiser_, 1e-6);
}

NloptSolver::~NloptSolver() {
  nlopt_destroy(optimiser_);
}

double NloptSolver::minimise(TrajectoryCost& cost, const ControlBounds& bounds,
                             Eigen::VectorXd& controls) {
  Objective data{&cost, controls, Eigen::VectorXd(controls.size())};
  nlopt_set_lower_bounds(optimiser_, bounds.lower.data());
  nlopt_set_upper_bounds(optimiser_, bounds.upper.data());
  nlopt_set_min_objective(optimiser_, &objective, &data);
  const Eigen::VectorXd start = bounds.clamp(controls);
  const double start_value = cost.evaluate(start);
  Eigen::VectorXd x = start;
  double value = start_value;
  const nlopt_result result = nlopt_optimize(optimiser_, x.data(), &value);
  // NLopt hands back its best point even when it stops early (round-off, evaluation limit); a
  // failure that left nothing usable keeps the start.
  if (result < 0 && result != NLOPT_ROUNDOFF_LIMITED) {
    controls = start;
    return start_value;
  }
  if (!std::isfinite(value) || value > start_value) {
    controls = start;
    return start_value;
  }
  controls = x;
  return value;
}

}  // namespace ari_social_sim::navigation
