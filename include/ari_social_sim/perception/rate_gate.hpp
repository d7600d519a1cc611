#pragma once

#include <optional>

namespace ari_social_sim::perception {

/// Which world states perception takes at a maximum rate (hri_perception_node's `~max_rate`,
/// and the batch tool's engine with the same value). A state closer than 0.999 of a period to the
/// last one taken is skipped: the small tolerance keeps a world that steps at exactly the maximum
/// rate from being thinned out by rounding. A state earlier than the last one taken (sim time
/// went backwards: /sim/reset, a bag that loops) is taken and counts from there, or perception
/// would stay silent until time caught up with where it was before.
class RateGate {
 public:
  /// `max_rate_hz` > 0 (the callers' configs check it).
  explicit RateGate(double max_rate_hz);

  /// True when a state at sim time `time_s` is due; it then is the last one taken.
  bool take(double time_s);

 private:
  double min_gap_s_;
  std::optional<double> last_taken_s_;
};

}  // namespace ari_social_sim::perception
