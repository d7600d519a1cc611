#include "ari_social_sim/world/head_nod.hpp"

#include <cmath>

namespace ari_social_sim::world {

double HeadNod::pitch_at(double time_s) const {
  if (time_s <= start_s || time_s >= end_s()) {
    return 0.0;
  }
  const double phase = std::sin(M_PI * (time_s - start_s) / cycle_s);
  return amplitude_rad * phase * phase;
}

}  // namespace ari_social_sim::world
