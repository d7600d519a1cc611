#include "ari_social_sim/audio/voice.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::audio {
namespace {

constexpr std::array<const char*, 7> kMaleVariants{"m1", "m2", "m3", "m4", "m5", "m6", "m7"};
constexpr std::array<const char*, 5> kFemaleVariants{"f1", "f2", "f3", "f4", "f5"};
constexpr const char* kAriVariant = "klatt";

bool known_variant(const std::string& variant) {
  const auto is = [&variant](const char* name) { return variant == name; };
  return std::any_of(kMaleVariants.begin(), kMaleVariants.end(), is) ||
         std::any_of(kFemaleVariants.begin(), kFemaleVariants.end(), is) || variant == kAriVariant;
}

void check_range(const char* field, int value, int low, int high) {
  if (value < low || value > high) {
    throw core::RequestError("voice: " + std::string(field) + ": expected " + std::to_string(low) +
                             ".." + std::to_string(high) + ", got " + std::to_string(value));
  }
}

// Speaking fundamental frequency falls through adult life for women and rises slightly for men
// after 60 (docs/references.md, "Voices"): a pitch offset in espeak-ng's 0..99 units.
int age_pitch_offset(model::Gender gender, double age_years) {
  const double years_past_30 = std::max(0.0, age_years - 30.0);
  if (gender == model::Gender::kFemale) {
    return -static_cast<int>(std::lround(years_past_30 * 0.3));
  }
  return age_years > 60.0 ? static_cast<int>(std::lround((age_years - 60.0) * 0.2)) : 0;
}

}  // namespace

std::string Voice::key() const {
  return variant + "/" + std::to_string(pitch) + "/" + std::to_string(pitch_range) + "/" +
         std::to_string(rate_wpm);
}

bool Voice::operator==(const Voice& other) const {
  return key() == other.key();
}

void check_voice(const Voice& voice) {
  if (!known_variant(voice.variant)) {
    throw core::RequestError("voice: variant: expected one of m1..m7, f1..f5 or klatt, got '" +
                             voice.variant + "'");
  }
  check_range("pitch", voice.pitch, 0, 99);
  check_range("pitch_range", voice.pitch_range, 0, 99);
  check_range("rate_wpm", voice.rate_wpm, 80, 450);
}

Voice voice_for(uint64_t seed, uint64_t human_id, model::Gender gender, double age_years) {
  core::Rng rng = core::rng_for(seed, core::rng_streams::kHumanVoice,
                                human_id % core::rng_streams::kHumanVoice.count);
  bool female = gender == model::Gender::kFemale;
  if (gender == model::Gender::kNonIdentified) {
    female = rng.uniform() < 0.5;
  }
  Voice voice;
  if (female) {
    voice.variant = kFemaleVariants[rng.uniform_index(kFemaleVariants.size())];
    voice.pitch = static_cast<int>(std::lround(rng.uniform(55.0, 75.0)));
  } else {
    voice.variant = kMaleVariants[rng.uniform_index(kMaleVariants.size())];
    voice.pitch = static_cast<int>(std::lround(rng.uniform(30.0, 50.0)));
  }
  voice.pitch = std::clamp(voice.pitch + age_pitch_offset(gender, age_years), 0, 99);
  voice.pitch_range = static_cast<int>(std::lround(rng.uniform(35.0, 65.0)));
  voice.rate_wpm = static_cast<int>(std::lround(rng.uniform(150.0, 190.0)));
  return voice;
}

Voice ari_voice() {
  return Voice{kAriVariant, 50, 40, 170};
}

}  // namespace ari_social_sim::audio
