#pragma once

#include <cstdint>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::model {

/// A person's gender as the world reports it: female, male or non-identified. Values match
/// HumanState.msg.
enum class Gender : uint8_t { kFemale = 1, kMale = 2, kNonIdentified = 3 };
/// A person's displayed emotion: neutral, happy, angry or disturbed. Values match HumanState.msg.
enum class Emotion : uint8_t { kNeutral = 0, kHappy = 1, kAngry = 2, kDisturbed = 3 };

/// How scene files, scenario scripts and world_node's spawn_human spell each value.
inline constexpr core::Choice<Gender> kGenders[] = {{Gender::kFemale, "female"},
                                                    {Gender::kMale, "male"},
                                                    {Gender::kNonIdentified, "non-identified"}};
inline constexpr core::Choice<Emotion> kEmotions[] = {{Emotion::kNeutral, "neutral"},
                                                      {Emotion::kHappy, "happy"},
                                                      {Emotion::kAngry, "angry"},
                                                      {Emotion::kDisturbed, "disturbed"}};

inline const char* to_string(Gender gender) {
  return core::choice_name(gender, kGenders);
}
inline const char* to_string(Emotion emotion) {
  return core::choice_name(emotion, kEmotions);
}

}  // namespace ari_social_sim::model
