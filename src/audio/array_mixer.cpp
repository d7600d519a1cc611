#include "ari_social_sim/audio/array_mixer.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::audio {
namespace {

constexpr double kSampleRate = model::kArraySampleRateHz;
// Half-width of the windowed-sinc fractional delay of the direct sound (sub-sample delays
// between microphones 64 mm apart are what localisers measure).
constexpr int kDelayHalfTaps = 4;
// Longest delay kept for a sound after its end: the farthest reflection in a large room.
constexpr int64_t kTailSamples = static_cast<int64_t>(0.2 * kSampleRate);

double db_to_gain(double db) {
  return std::pow(10.0, db / 20.0);
}

// The signal at fractional index `t` (0 outside it): windowed sinc for the direct sound, linear
// for reflections, whose exact phase no listener resolves.
float sample_at(const std::vector<float>& signal, double t, bool exact) {
  const auto at = [&signal](long i) {
    return i >= 0 && i < static_cast<long>(signal.size()) ? signal[i] : 0.0f;
  };
  const long base = static_cast<long>(std::floor(t));
  const double frac = t - base;
  if (!exact) {
    return static_cast<float>((1.0 - frac) * at(base) + frac * at(base + 1));
  }
  double sum = 0.0;
  for (long k = base - kDelayHalfTaps + 1; k <= base + kDelayHalfTaps; ++k) {
    const double x = t - k;
    const double sinc = std::abs(x) < 1e-9 ? 1.0 : std::sin(M_PI * x) / (M_PI * x);
    const double window = 0.5 + 0.5 * std::cos(M_PI * x / kDelayHalfTaps);
    sum += at(k) * sinc * window;
  }
  return static_cast<float>(sum);
}

// Full scale +-1 as 16-bit samples, clipped as an ADC clips.
std::vector<int16_t> to_pcm(const std::vector<float>& values) {
  std::vector<int16_t> pcm(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    pcm[i] = static_cast<int16_t>(
        std::lround(std::clamp(values[i], -1.0f, 32767.0f / 32768.0f) * 32768.0f));
  }
  return pcm;
}

std::shared_ptr<const std::vector<float>> unit_rms(const std::vector<float>& signal) {
  double energy = 0.0;
  for (const float s : signal) {
    energy += double(s) * s;
  }
  const double rms = std::sqrt(energy / std::max<size_t>(signal.size(), 1));
  auto scaled = std::make_shared<std::vector<float>>(signal);
  if (rms > 1e-9) {
    for (float& s : *scaled) {
      s = static_cast<float>(s / rms);
    }
  }
  return scaled;
}

}  // namespace

ArrayMixer::ArrayMixer(const RoomSettings& settings, std::vector<Wall> walls, uint64_t seed)
    : settings_(settings),
      walls_(std::move(walls)),
      noise_(core::rng_for(seed, core::rng_streams::kRoomNoise)) {
  check_room_settings(settings_);
  for (size_t m = 0; m < kMicrophones; ++m) {
    reverbs_.emplace_back(settings_.rt60_s, model::kArraySampleRateHz, m);
  }
}

void ArrayMixer::add(PlacedSound sound) {
  if (!sound.signal || sound.signal->empty()) {
    return;
  }
  sound.signal = unit_rms(*sound.signal);
  sounds_.push_back(std::move(sound));
}

void ArrayMixer::stop_source(uint64_t source, int64_t sample) {
  for (PlacedSound& sound : sounds_) {
    const int64_t kept = sample - sound.start_sample;
    if (sound.source == source && kept < static_cast<int64_t>(sound.signal->size())) {
      auto cut = std::make_shared<std::vector<float>>(
          sound.signal->begin(), sound.signal->begin() + std::max<int64_t>(kept, 0));
      sound.signal = cut;
    }
  }
}

void ArrayMixer::set_source_position(uint64_t source, const Eigen::Vector3d& position) {
  positions_[source] = position;
}

void ArrayMixer::set_array_pose(const Eigen::Isometry3d& X_world_array) {
  X_world_array_ = X_world_array;
}

bool ArrayMixer::voice_at(int64_t sample) const {
  return std::any_of(sounds_.begin(), sounds_.end(), [sample](const PlacedSound& sound) {
    return !sound.from_ari && sample >= sound.start_sample &&
           sample < sound.start_sample + static_cast<int64_t>(sound.signal->size());
  });
}

void ArrayMixer::add_sound(const PlacedSound& sound, size_t count,
                           std::array<std::vector<float>, kMicrophones>& heard,
                           std::vector<float>& playback) const {
  const double level =
      db_to_gain(sound.from_ari ? settings_.ari_speech_level_dbfs : settings_.speech_level_dbfs);
  const double offset = static_cast<double>(next_sample_ - sound.start_sample);
  if (sound.from_ari) {
    for (size_t n = 0; n < count; ++n) {
      playback[n] += static_cast<float>(level * sample_at(*sound.signal, offset + n, false));
    }
  }
  const auto position = positions_.find(sound.source);
  if (position == positions_.end()) {
    return;  // not placed yet: heard from the next chunk on
  }
  for (size_t m = 0; m < kMicrophones; ++m) {
    const model::MountPoint& mic = model::kArrayMicrophones[m];
    const Eigen::Vector3d at = X_world_array_ * Eigen::Vector3d(mic.x_m, mic.y_m, mic.z_m);
    const std::vector<SoundPath> paths = sound_paths(position->second, at, walls_, settings_);
    for (size_t p = 0; p < paths.size(); ++p) {
      const double delay = paths[p].delay_s * kSampleRate;
      const double gain = level * paths[p].gain;
      for (size_t n = 0; n < count; ++n) {
        heard[m][n] +=
            static_cast<float>(gain * sample_at(*sound.signal, offset + n - delay, p == 0));
      }
    }
  }
}

ArrayChunk ArrayMixer::render(size_t count) {
  std::array<std::vector<float>, kMicrophones> others;
  std::array<std::vector<float>, kMicrophones> robot;
  std::vector<float> playback(count, 0.0f);
  for (size_t m = 0; m < kMicrophones; ++m) {
    others[m].assign(count, 0.0f);
    robot[m].assign(count, 0.0f);
  }
  for (const PlacedSound& sound : sounds_) {
    add_sound(sound, count, sound.from_ari ? robot : others, playback);
  }
  // Raw microphones: everyone's direct and early sound plus the late tail they excite.
  std::array<std::vector<float>, kMicrophones> raw;
  std::vector<float> processed(count, 0.0f);
  for (size_t m = 0; m < kMicrophones; ++m) {
    raw[m].resize(count);
    for (size_t n = 0; n < count; ++n) {
      raw[m][n] = others[m][n] + robot[m][n];
      processed[n] += others[m][n] / kMicrophones;
    }
    const std::vector<float> dry = raw[m];
    reverbs_[m].process(dry, static_cast<float>(settings_.reverb_level), raw[m]);
  }
  add_noise(raw, processed);
  ArrayChunk chunk;
  chunk.first_sample = next_sample_;
  chunk.channels[0] = to_pcm(processed);
  for (size_t m = 0; m < kMicrophones; ++m) {
    chunk.channels[1 + m] = to_pcm(raw[m]);
  }
  chunk.channels[5] = to_pcm(playback);
  next_sample_ += static_cast<int64_t>(count);
  drop_ended_sounds();
  return chunk;
}

void ArrayMixer::add_noise(std::array<std::vector<float>, kMicrophones>& raw,
                           std::vector<float>& processed) {
  // Drawn sample by sample and microphone by microphone: the same draws whatever the chunk sizes.
  const double gain = db_to_gain(settings_.noise_level_dbfs);
  for (size_t n = 0; n < processed.size(); ++n) {
    double sum = 0.0;
    for (size_t m = 0; m < kMicrophones; ++m) {
      const double noise = gain * noise_.normal(0.0, 1.0);
      raw[m][n] += static_cast<float>(noise);
      sum += noise;
    }
    processed[n] += static_cast<float>(sum / kMicrophones);
  }
}

void ArrayMixer::drop_ended_sounds() {
  const auto ended = [this](const PlacedSound& sound) {
    return sound.start_sample + static_cast<int64_t>(sound.signal->size()) + kTailSamples <
           next_sample_;
  };
  sounds_.erase(std::remove_if(sounds_.begin(), sounds_.end(), ended), sounds_.end());
}

}  // namespace ari_social_sim::audio
