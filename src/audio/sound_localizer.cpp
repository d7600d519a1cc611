#include "ari_social_sim/audio/sound_localizer.hpp"

#include <cmath>
#include <complex>
#include <opencv2/core.hpp>

#include "ari_social_sim/audio/room_acoustics.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/model/ari_sensor_geometry.hpp"

namespace ari_social_sim::audio {
namespace {

constexpr int kAzimuthSteps = 360;
// Below this mean square a frame is taken to be silence (about -70 dBFS).
constexpr double kSilentEnergy = 1e-7;
// Speech energy lies below 4 kHz; above it the 64 mm aperture aliases.
constexpr double kMaxFrequencyHz = 4000.0;

using Spectrum = std::vector<std::complex<double>>;

Spectrum spectrum_of(const std::vector<float>& frame) {
  cv::Mat in(1, static_cast<int>(frame.size()), CV_64F);
  for (size_t i = 0; i < frame.size(); ++i) {
    in.at<double>(0, static_cast<int>(i)) = frame[i];
  }
  cv::Mat out;
  cv::dft(in, out, cv::DFT_COMPLEX_OUTPUT);
  Spectrum spectrum(frame.size() / 2 + 1);
  for (size_t k = 0; k < spectrum.size(); ++k) {
    const cv::Vec2d bin = out.at<cv::Vec2d>(0, static_cast<int>(k));
    spectrum[k] = {bin[0], bin[1]};
  }
  return spectrum;
}

double mean_square(const std::vector<float>& frame) {
  double sum = 0.0;
  for (const float s : frame) {
    sum += double(s) * s;
  }
  return sum / frame.size();
}

}  // namespace

std::optional<SoundDirection> locate_sound(const std::array<std::vector<float>, 4>& microphones) {
  const size_t length = microphones[0].size();
  ARI_CHECK(length >= 64 && (length & (length - 1)) == 0);
  if (mean_square(microphones[0]) < kSilentEnergy) {
    return std::nullopt;
  }
  std::array<Spectrum, 4> spectra;
  for (size_t m = 0; m < 4; ++m) {
    ARI_CHECK(microphones[m].size() == length);
    spectra[m] = spectrum_of(microphones[m]);
  }
  const double bin_hz = static_cast<double>(model::kArraySampleRateHz) / length;
  const size_t bins = std::min(spectra[0].size(), static_cast<size_t>(kMaxFrequencyHz / bin_hz));
  std::array<double, kAzimuthSteps> power{};
  for (size_t a = 0; a < 4; ++a) {
    for (size_t b = a + 1; b < 4; ++b) {
      const Eigen::Vector2d baseline(
          model::kArrayMicrophones[a].x_m - model::kArrayMicrophones[b].x_m,
          model::kArrayMicrophones[a].y_m - model::kArrayMicrophones[b].y_m);
      for (size_t k = 1; k < bins; ++k) {
        std::complex<double> cross = spectra[a][k] * std::conj(spectra[b][k]);
        cross /= std::max(std::abs(cross), 1e-12);  // the phase transform
        const double omega = 2.0 * M_PI * k * bin_hz;
        for (int step = 0; step < kAzimuthSteps; ++step) {
          const double azimuth = step * 2.0 * M_PI / kAzimuthSteps;
          // A far source at `azimuth` reaches microphone a earlier by the baseline's projection.
          const double lead_s =
              baseline.dot(Eigen::Vector2d(std::cos(azimuth), std::sin(azimuth))) /
              kSpeedOfSoundMps;
          power[step] += (cross * std::polar(1.0, -omega * lead_s)).real();
        }
      }
    }
  }
  int best = 0;
  for (int step = 0; step < kAzimuthSteps; ++step) {
    best = power[step] > power[best] ? step : best;
  }
  SoundDirection direction;
  direction.azimuth_rad = std::remainder(best * 2.0 * M_PI / kAzimuthSteps, 2.0 * M_PI);
  direction.coherence = power[best] / (6.0 * static_cast<double>(bins - 1));
  return direction;
}

}  // namespace ari_social_sim::audio
