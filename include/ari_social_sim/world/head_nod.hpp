#pragma once

namespace ari_social_sim::world {

/// A listener's head nod, a backchannel without words (issue 31): the head dips and comes back
/// up `cycles` times, each dip lasting `cycle_s`, at most `amplitude_rad` below level.
struct HeadNod {
  double start_s{0.0};
  int cycles{1};
  double cycle_s{0.4};
  double amplitude_rad{0.17};

  double end_s() const { return start_s + cycles * cycle_s; }
  /// The head's pitch (rad, positive: down) at sim time `time_s`: 0 outside the nod, a
  /// sin^2 dip in each cycle, so that the head leaves and returns to level smoothly.
  double pitch_at(double time_s) const;
};

}  // namespace ari_social_sim::world
