#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace ari_social_sim::world {

/// User-facing identifier of any object in the world (wall, furniture, human, ARI), unique and
/// positive (seed 3.2: i in N+). 0 means "none".
using ObjectId = uint32_t;
constexpr ObjectId kNoObject = 0;

/// Seed 3.3: gender in {female, male, non-identified}. Values match HumanState.msg.
enum class Gender : uint8_t { kFemale = 1, kMale = 2, kNonIdentified = 3 };
/// Seed 3.3: emotion in {neutral, happy, angry, disturbed}. Values match HumanState.msg.
enum class Emotion : uint8_t { kNeutral = 0, kHappy = 1, kAngry = 2, kDisturbed = 3 };

std::optional<Gender> parse_gender(const std::string& text);
std::optional<Emotion> parse_emotion(const std::string& text);
const char* to_string(Gender gender);
const char* to_string(Emotion emotion);

}  // namespace ari_social_sim::world
