#pragma once

#include <cstdint>
#include <deque>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::rendering {

/// Which leg a standing person bears their weight on, over time. Relaxed standing is lopsided:
/// people lean on one leg and now and then move over to the other (Prado-Rico and Duarte 2019).
/// Over half an hour of free standing, Duarte and Zatsiorsky (1999) saw a sideways shift of the
/// weight every 199 +- 148 s and a fidget (over to the other leg and back) every 49 +- 16 s: both
/// are drawn here, as log-normal intervals with those means and spreads. The schedule is a
/// function of (seed, person id) and time alone, so any choice of frames shows the same moves.
class WeightShifts {
 public:
  WeightShifts(uint64_t seed, uint32_t person_id);

  /// Where the weight is at time_s: +1 on the figure's left leg, -1 on its right, in between
  /// while it moves over. Any time_s >= 0, in any order.
  double load_side(double time_s);

 private:
  struct Change {
    double time_s;
    double side;  // the leg the weight moves to, +1 left, -1 right
  };
  void restart();
  void plan_until(double time_s);
  void add_change(double time_s, double side);
  void forget_before(double time_s);

  uint64_t seed_;
  uint32_t person_id_;
  core::Rng rng_{0};
  double side_{1.0};  // after the last planned change
  double next_shift_s_{0.0};
  double next_fidget_s_{0.0};
  double still_from_s_{0.0};       // the last planned move's end: the next one starts no earlier
  std::deque<Change> changes_;     // planned, in time order; those long past are forgotten
  double side_before_{1.0};        // before changes_.front()
  double forgotten_until_s_{0.0};  // earlier times need a restart()
};

}  // namespace ari_social_sim::rendering
