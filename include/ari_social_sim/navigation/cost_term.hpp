#pragma once

#include <Eigen/Core>

#include "ari_social_sim/navigation/mpc_problem.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/unicycle_model.hpp"

namespace ari_social_sim::navigation {

/// One term of the MPC cost: scores a whole rollout (states 1..N and the controls that led there)
/// and, when asked, adds its gradient with respect to the states and the controls. Terms read plain
/// data and keep no state between calls, so each is tested on its own.
class CostTerm {
 public:
  virtual ~CostTerm() = default;
  virtual const char* name() const = 0;
  /// Cost of `rollout` under `controls` (3 N values) for `problem`; adds d(cost) to `gradient`
  /// when it is not null.
  virtual double evaluate(const MpcProblem& problem, const Rollout& rollout,
                          const Eigen::VectorXd& controls, RolloutGradient* gradient) const = 0;
};

/// max(0, x)^2 and its derivative, the penalty shape of every margin term.
inline double hinge_squared(double x, double* derivative) {
  if (x <= 0.0) {
    *derivative = 0.0;
    return 0.0;
  }
  *derivative = 2.0 * x;
  return x * x;
}

}  // namespace ari_social_sim::navigation
