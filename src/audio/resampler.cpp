#include "ari_social_sim/audio/resampler.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::audio {
namespace {

// Half the filter's length in input samples: 16 zero crossings each side keep the pass band flat
// to within 0.1 dB up to 90 % of the cut-off.
constexpr int kHalfTaps = 16;

double sinc(double x) {
  return std::abs(x) < 1e-12 ? 1.0 : std::sin(M_PI * x) / (M_PI * x);
}

// Blackman window over [-1, 1].
double window(double x) {
  return 0.42 + 0.5 * std::cos(M_PI * x) + 0.08 * std::cos(2.0 * M_PI * x);
}

}  // namespace

std::vector<float> resample(const std::vector<float>& samples, int from_hz, int to_hz) {
  ARI_CHECK(from_hz > 0 && to_hz > 0);
  if (from_hz == to_hz || samples.empty()) {
    return samples;
  }
  const double step = static_cast<double>(from_hz) / to_hz;  // input samples per output sample
  const double cutoff = std::min(1.0, 1.0 / step);           // of the input's Nyquist frequency
  const double reach = kHalfTaps / cutoff;
  const size_t count = static_cast<size_t>(std::floor(samples.size() / step));
  std::vector<float> out(count);
  const long last = static_cast<long>(samples.size()) - 1;
  for (size_t n = 0; n < count; ++n) {
    const double centre = n * step;
    const long first = std::max(0L, static_cast<long>(std::ceil(centre - reach)));
    const long end = std::min(last, static_cast<long>(std::floor(centre + reach)));
    double sum = 0.0;
    for (long k = first; k <= end; ++k) {
      const double offset = k - centre;
      sum += samples[k] * cutoff * sinc(cutoff * offset) * window(offset / reach);
    }
    out[n] = static_cast<float>(sum);
  }
  return out;
}

}  // namespace ari_social_sim::audio
