#include "ari_social_sim/navigation/trajectory_cost.hpp"

#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/navigation/agent_clearance_cost.hpp"
#include "ari_social_sim/navigation/control_cost.hpp"
#include "ari_social_sim/navigation/goal_cost.hpp"
#include "ari_social_sim/navigation/group_space_cost.hpp"
#include "ari_social_sim/navigation/heading_cost.hpp"
#include "ari_social_sim/navigation/obstacle_cost.hpp"
#include "ari_social_sim/navigation/personal_space_cost.hpp"
#include "ari_social_sim/navigation/view_cost.hpp"

namespace ari_social_sim::navigation {

TrajectoryCost::TrajectoryCost(const MpcConfig& config, const UnicycleModel& model)
    : model_(model) {
  const CostWeights& w = config.weights;
  const FootprintModel& footprint = model.footprint();
  const double dt = config.step_s;
  terms_.push_back(std::make_unique<GoalCost>(w.goal, w.terminal, config.goal_huber_m));
  if (w.heading > 0.0 || w.path_heading > 0.0) {
    terms_.push_back(
        std::make_unique<HeadingCost>(w.heading, w.path_heading, config.heading_radius_m));
  }
  if (w.obstacle > 0.0) {
    terms_.push_back(
        std::make_unique<ObstacleCost>(w.obstacle, footprint, config.obstacle_margin_m));
  }
  if (w.agent_clearance > 0.0) {
    terms_.push_back(std::make_unique<AgentClearanceCost>(w.agent_clearance, footprint,
                                                          config.personal_space.person_radius_m,
                                                          config.agent_margin_m, dt));
  }
  if (w.personal_space > 0.0 || w.personal_space_edge > 0.0) {
    terms_.push_back(std::make_unique<PersonalSpaceCost>(w.personal_space, w.personal_space_edge,
                                                         footprint, config.personal_space,
                                                         config.personal_space_margin_sigmas, dt));
  }
  if (w.group_space > 0.0 || w.ospace_edge > 0.0) {
    terms_.push_back(std::make_unique<GroupSpaceCost>(
        w.group_space, w.ospace_edge, footprint, config.personal_space, config.ospace_margin_m));
  }
  terms_.push_back(std::make_unique<ControlCost>(w, config.limits, dt));
  if (w.view > 0.0 || w.pan_limit > 0.0) {
    // Aim 0.05 rad inside head_1_joint's limit, as ARI's soft limits do (ari_robot's URDF).
    terms_.push_back(std::make_unique<ViewCost>(w.view, w.pan_limit, footprint,
                                                config.limits.head_pan_limit_rad - 0.05));
  }
}

double TrajectoryCost::evaluate(const Eigen::VectorXd& controls, Eigen::VectorXd* gradient) {
  ARI_DCHECK(problem_ != nullptr);
  ++evaluations_;
  model_.rollout(problem_->start, controls, rollout_);
  RolloutGradient* g = nullptr;
  if (gradient != nullptr) {
    gradient_.reset(rollout_.steps());
    g = &gradient_;
  }
  double total = 0.0;
  for (const auto& term : terms_) {
    total += term->evaluate(*problem_, rollout_, controls, g);
  }
  if (gradient != nullptr) {
    model_.backpropagate(rollout_, controls, gradient_);
    *gradient = gradient_.controls;
  }
  return total;
}

std::vector<TermCost> TrajectoryCost::breakdown(const Eigen::VectorXd& controls) {
  model_.rollout(problem_->start, controls, rollout_);
  std::vector<TermCost> costs;
  for (const auto& term : terms_) {
    costs.push_back({term->name(), term->evaluate(*problem_, rollout_, controls, nullptr)});
  }
  return costs;
}

}  // namespace ari_social_sim::navigation
