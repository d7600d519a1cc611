#include "ari_social_sim/dialogue/agenda.hpp"

#include <algorithm>

namespace ari_social_sim::dialogue {
namespace {

bool is_open(GoalStatus status) {
  return status == GoalStatus::kWaiting || status == GoalStatus::kStated;
}

constexpr int kTargetTries = 20;  // draws before accepting a repeated target

}  // namespace

Agenda::Agenda(std::vector<TrackedGoal> goals) : goals_(std::move(goals)) {}

Agenda Agenda::sample(const Domain& domain, const GoalCountModel& counts,
                      const std::vector<std::string>& roles, core::Rng& rng) {
  const unsigned count = counts.counts[rng.categorical(counts.probabilities)];
  std::vector<TrackedGoal> goals;
  for (unsigned i = 0; i < count; ++i) {
    std::vector<std::string> owners;
    if (roles.size() > 1 && rng.bernoulli(counts.joint_share)) {
      owners = roles;
    } else {
      owners = {roles[rng.uniform_index(roles.size())]};
    }
    Goal goal;
    for (int attempt = 0; attempt < kTargetTries; ++attempt) {
      goal = domain.sample_goal(owners, rng);
      const bool repeated = std::any_of(goals.begin(), goals.end(), [&goal](const TrackedGoal& g) {
        return g.goal.same_target(goal);
      });
      if (!repeated) {
        break;
      }
    }
    goals.push_back(TrackedGoal{std::move(goal)});
  }
  return Agenda(std::move(goals));
}

bool Agenda::owns(const TrackedGoal& goal, const std::string& role) {
  return std::find(goal.goal.owners.begin(), goal.goal.owners.end(), role) !=
         goal.goal.owners.end();
}

int Agenda::next_waiting(const std::string& role, core::Rng& rng) const {
  int own = -1;
  int shared = -1;
  double own_size = 0;
  double shared_size = 0;
  for (size_t i = 0; i < goals_.size(); ++i) {
    const TrackedGoal& g = goals_[i];
    if (g.status != GoalStatus::kWaiting || !owns(g, role)) {
      continue;
    }
    if (g.goal.is_joint()) {
      shared = shared < 0 ? static_cast<int>(i) : shared;
      shared_size += 1;
    } else {
      own = own < 0 ? static_cast<int>(i) : own;
      own_size += 1;
    }
  }
  if (own < 0 || shared < 0) {
    return own >= 0 ? own : shared;
  }
  return rng.uniform() * (own_size + shared_size) < own_size ? own : shared;
}

int Agenda::open_goal(const std::string& role) const {
  int best = -1;
  for (size_t i = 0; i < goals_.size(); ++i) {
    const TrackedGoal& g = goals_[i];
    if (g.status == GoalStatus::kStated && owns(g, role) &&
        (best < 0 || g.stated_order > goals_[best].stated_order)) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

int Agenda::focus() const {
  int best = -1;
  for (size_t i = 0; i < goals_.size(); ++i) {
    if (goals_[i].status == GoalStatus::kStated &&
        (best < 0 || goals_[i].stated_order > goals_[best].stated_order)) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

std::vector<int> Agenda::closable(const std::string& role) const {
  std::vector<int> indices;
  for (size_t i = 0; i < goals_.size(); ++i) {
    if (goals_[i].status == GoalStatus::kResolved && owns(goals_[i], role)) {
      indices.push_back(static_cast<int>(i));
    }
  }
  return indices;
}

void Agenda::mark_stated(int index) {
  TrackedGoal& g = goals_[index];
  g.status = GoalStatus::kStated;
  g.asks += 1;
  g.stated_order = stated_counter_++;
}

bool Agenda::done(const std::string& role) const {
  return std::none_of(goals_.begin(), goals_.end(),
                      [&role](const TrackedGoal& g) { return is_open(g.status) && owns(g, role); });
}

bool Agenda::all_done() const {
  return std::none_of(goals_.begin(), goals_.end(),
                      [](const TrackedGoal& g) { return is_open(g.status); });
}

}  // namespace ari_social_sim::dialogue
