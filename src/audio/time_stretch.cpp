#include "ari_social_sim/audio/time_stretch.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::audio {
namespace {

constexpr long kFrame = 320;       // 20 ms
constexpr long kHop = kFrame / 2;  // output hop
constexpr long kSearch = 80;       // +-5 ms

float at(const std::vector<float>& samples, long i) {
  return i >= 0 && i < static_cast<long>(samples.size()) ? samples[i] : 0.0f;
}

// The offset within +-kSearch of `nominal` whose frame best matches `target` (cross-correlation).
long best_offset(const std::vector<float>& samples, long nominal, long target) {
  long best = 0;
  double best_score = -1e300;
  for (long delta = -kSearch; delta <= kSearch; delta += 2) {
    double score = 0.0;
    for (long i = 0; i < kFrame; i += 2) {
      score += double(at(samples, nominal + delta + i)) * at(samples, target + i);
    }
    if (score > best_score) {
      best_score = score;
      best = delta;
    }
  }
  return best;
}

}  // namespace

std::vector<float> stretch_to(const std::vector<float>& samples, size_t length) {
  if (samples.empty() || length == 0) {
    return std::vector<float>(length, 0.0f);
  }
  if (length == samples.size()) {
    return samples;
  }
  const double analysis_hop = kHop * static_cast<double>(samples.size()) / length;
  std::vector<double> out(length + kFrame, 0.0), weight(length + kFrame, 0.0);
  long previous = 0;
  for (long k = 0; k * kHop < static_cast<long>(length); ++k) {
    const long nominal = static_cast<long>(std::lround(k * analysis_hop));
    const long start = k == 0 ? 0 : nominal + best_offset(samples, nominal, previous + kHop);
    for (long i = 0; i < kFrame; ++i) {
      const double window = 0.5 - 0.5 * std::cos(2.0 * M_PI * i / kFrame);
      out[k * kHop + i] += window * at(samples, start + i);
      weight[k * kHop + i] += window;
    }
    previous = start;
  }
  std::vector<float> result(length);
  for (size_t i = 0; i < length; ++i) {
    result[i] = static_cast<float>(weight[i] > 1e-6 ? out[i] / weight[i] : 0.0);
  }
  return result;
}

}  // namespace ari_social_sim::audio
