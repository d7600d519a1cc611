#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "ari_social_sim/navigation/cost_term.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/unicycle_model.hpp"

namespace ari_social_sim::navigation {

/// One term's share of a trajectory's cost.
struct TermCost {
  const char* name;
  double cost;
};

/// The MPC objective J(u): rolls the controls out through the model and sums the enabled cost
/// terms (those with a non-zero weight), with the exact gradient dJ/du by reverse mode through the
/// dynamics. Holds its scratch rollout and gradient, so repeated evaluations do not allocate.
class TrajectoryCost {
 public:
  TrajectoryCost(const MpcConfig& config, const UnicycleModel& model);

  /// The problem the next evaluations score; it must outlive them.
  void set_problem(const MpcProblem& problem) { problem_ = &problem; }
  /// J(controls); fills `gradient` (3 N values) when it is not null.
  double evaluate(const Eigen::VectorXd& controls, Eigen::VectorXd* gradient = nullptr);
  /// Each term's cost of `controls`.
  std::vector<TermCost> breakdown(const Eigen::VectorXd& controls);
  /// The rollout of the last evaluation.
  const Rollout& rollout() const { return rollout_; }
  const UnicycleModel& model() const { return model_; }
  int evaluations() const { return evaluations_; }
  void reset_evaluations() { evaluations_ = 0; }

 private:
  const UnicycleModel& model_;
  std::vector<std::unique_ptr<CostTerm>> terms_;
  const MpcProblem* problem_{nullptr};
  Rollout rollout_;
  RolloutGradient gradient_;
  int evaluations_{0};
};

}  // namespace ari_social_sim::navigation
