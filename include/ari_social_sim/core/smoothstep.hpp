#pragma once

#include <algorithm>

namespace ari_social_sim::core {

/// 0 below 0, 1 above 1, and a smooth S in between (zero slope at both ends): for moves that
/// start and settle gently.
inline double smoothstep(double x) {
  const double t = std::clamp(x, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace ari_social_sim::core
