#include "ari_social_sim/perception/rate_gate.hpp"

namespace ari_social_sim::perception {

RateGate::RateGate(double max_rate_hz) : min_gap_s_(0.999 * (1.0 / max_rate_hz)) {}

bool RateGate::take(double time_s) {
  if (last_taken_s_ && time_s >= *last_taken_s_ && time_s - *last_taken_s_ < min_gap_s_) {
    return false;
  }
  last_taken_s_ = time_s;
  return true;
}

}  // namespace ari_social_sim::perception
