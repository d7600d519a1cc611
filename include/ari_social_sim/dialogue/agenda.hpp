#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/goal.hpp"
#include "ari_social_sim/dialogue/user_model.hpp"

namespace ari_social_sim::dialogue {

/// Where a goal is in the dialogue.
enum class GoalStatus {
  kWaiting,   ///< in its owner's agenda (or the shared pool), not yet stated to ARI
  kStated,    ///< asked, no satisfying answer yet
  kResolved,  ///< answered (by ARI or the other human) or honestly declined
  kClosed,    ///< resolved and acknowledged by a user (CG)
  kFailed,    ///< given up: too many asks or out of patience
};

struct TrackedGoal {
  Goal goal;
  GoalStatus status{GoalStatus::kWaiting};
  int asks{0};            ///< times stated to ARI
  int stated_order{-1};   ///< when it was last stated (higher = more recent)
  bool satisfied{false};  ///< resolved with the right answer (or a cant-help ARI could not avoid)
};

/// The goals of one dialogue: one agenda per human (goals it owns alone, in order) plus the shared
/// pool of joint goals either owner may raise (the project's own model, docs/dialogue.md).
class Agenda {
 public:
  Agenda() = default;
  explicit Agenda(std::vector<TrackedGoal> goals);

  /// Draws the number of goals from `counts`, each joint with P = counts.joint_share (when there
  /// are two humans or more) or owned by one uniformly drawn role, targets drawn from the domain
  /// without repeats.
  static Agenda sample(const Domain& domain, const GoalCountModel& counts,
                       const std::vector<std::string>& roles, core::Rng& rng);

  std::vector<TrackedGoal>& goals() { return goals_; }
  const std::vector<TrackedGoal>& goals() const { return goals_; }

  static bool owns(const TrackedGoal& goal, const std::string& role);
  /// Next waiting goal `role` may raise: the front of its own agenda or of the shared pool
  /// (between the two with P proportional to their sizes); -1 if none.
  int next_waiting(const std::string& role, core::Rng& rng) const;
  /// Most recently stated goal of `role` still unresolved; -1 if none.
  int open_goal(const std::string& role) const;
  /// Most recently stated unresolved goal of anyone; -1 if none.
  int focus() const;
  /// Resolved goals of `role` not closed yet.
  std::vector<int> closable(const std::string& role) const;
  /// Marks `index` stated now.
  void mark_stated(int index);
  /// No waiting or stated goal is left for `role`.
  bool done(const std::string& role) const;
  bool all_done() const;

 private:
  std::vector<TrackedGoal> goals_;
  int stated_counter_{0};
};

}  // namespace ari_social_sim::dialogue
