#include "ari_social_sim/core/sim_timer.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::core {

SimTimer::SimTimer(double rate_hz)
    : period_ns_(std::max<int64_t>(1, std::llround(1e9 / rate_hz))), next_ns_(period_ns_) {}

bool SimTimer::due(double now_s) {
  const int64_t now_ns = std::llround(now_s * 1e9);
  if (last_ns_ && now_ns < *last_ns_) {
    next_ns_ = now_ns + period_ns_;
  }
  last_ns_ = now_ns;
  if (now_ns < next_ns_) {
    return false;
  }
  // The multiples the clock passed at once run as one.
  next_ns_ += ((now_ns - next_ns_) / period_ns_ + 1) * period_ns_;
  return true;
}

}  // namespace ari_social_sim::core
