#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace ari_social_sim::model {

/// A person's gender as the world reports it: female, male or non-identified. Values match
/// HumanState.msg.
enum class Gender : uint8_t { kFemale = 1, kMale = 2, kNonIdentified = 3 };
/// A person's displayed emotion: neutral, happy, angry or disturbed. Values match HumanState.msg.
enum class Emotion : uint8_t { kNeutral = 0, kHappy = 1, kAngry = 2, kDisturbed = 3 };

/// The texts parse_gender and parse_emotion take, as a refusal names them.
constexpr char kGenderChoices[] = "female, male or non-identified";
constexpr char kEmotionChoices[] = "neutral, happy, angry or disturbed";

std::optional<Gender> parse_gender(const std::string& text);
std::optional<Emotion> parse_emotion(const std::string& text);
const char* to_string(Gender gender);
const char* to_string(Emotion emotion);

}  // namespace ari_social_sim::model
