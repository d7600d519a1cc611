#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "ari_social_sim/rendering/people_figures.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

// The people as ari_physics_node drew them in its camera images, rebuilt from the world states it
// drew them from: a reader of those images (hri_perception_node's ~crops) finds each person's
// figure where the image shows it without receiving the rendered labels.

namespace ari_social_sim::rendering {

class DrawnPeople {
 public:
  /// How many world states are kept: two seconds of world_node's default 0.05 s step, more than
  /// an image waits for its camera pose.
  static constexpr size_t kHistory = 40;
  /// The world's step assumed while a single state is known (world_node's default).
  static constexpr double kDefaultWorldStep_s = 0.05;

  /// `appearance_seed`: ari_physics_node's, so that each person's figure is the one it drew.
  explicit DrawnPeople(uint64_t appearance_seed);

  /// Keeps the people of the world state stamped `time_s`; a state earlier than the last (the
  /// world was reset) starts the history afresh.
  void add_state(double time_s, std::vector<world::HumanSnapshot> humans);
  bool empty() const { return states_.empty(); }
  /// Whether the world state an image stamped `time_s` was drawn from has come (one stamped no
  /// earlier): until then pose_at would pose an older state, a world step behind the image.
  bool has_state_for(double time_s) const;

  /// Poses the figures as the physics drew them in an image stamped `time_s` (empty() must be
  /// false). The physics receives the world state stamped s with the clock's tick to s, before
  /// it steps (and renders) from the previous state's stamp s_prev to s, and walks the people on
  /// from their state at s by their velocity times the time since it received it (ari_physics,
  /// step 4): an image stamped in (s_prev, s] shows the state s walked on by time_s - s_prev, one
  /// world step ahead of the truth at time_s, their walked distance (the gait's phase) walked on
  /// alike. The figures' time never goes backwards: the gestures follow speech with it.
  const std::vector<PosedPerson>& pose_at(double time_s);

 private:
  PeopleFigures figures_;
  // The people of the last world states (sim time, people), oldest first.
  std::deque<std::pair<double, std::vector<world::HumanSnapshot>>> states_;
  double figures_time_s_{0.0};
};

}  // namespace ari_social_sim::rendering
