#pragma once

#include <cstdint>
#include <optional>

namespace ari_social_sim::core {

/// When a periodic callback runs on sim time, as a roscpp timer fires on /clock, for the engine
/// that runs the nodes' callbacks in-process (a node's own timer is roscpp's). Times are counted
/// in whole nanoseconds, as ros::Time counts them, so that a period that divides the world's step
/// (20 Hz at 0.05 s) fires at exactly the steps a node's timer fires at. The first run is one
/// period after the start; then each time the clock reaches the next multiple of the period. A
/// clock that jumps past several multiples runs the callback once (roscpp fires it for each, but
/// at one sim time: the nodes skip the repeats). A clock that goes backwards (/sim/reset) restarts
/// the timer one period after it.
class SimTimer {
 public:
  /// `rate_hz` > 0 (the callers' configs check it).
  explicit SimTimer(double rate_hz);

  /// True when the callback runs at sim time `now_s` (the world's time after a step).
  bool due(double now_s);

 private:
  int64_t period_ns_;
  int64_t next_ns_;
  std::optional<int64_t> last_ns_;
};

}  // namespace ari_social_sim::core
