#include "ari_social_sim/model/person_attributes.hpp"

namespace ari_social_sim::model {

std::optional<Gender> parse_gender(const std::string& text) {
  if (text == "female")
    return Gender::kFemale;
  if (text == "male")
    return Gender::kMale;
  if (text == "non-identified")
    return Gender::kNonIdentified;
  return std::nullopt;
}

std::optional<Emotion> parse_emotion(const std::string& text) {
  if (text == "neutral")
    return Emotion::kNeutral;
  if (text == "happy")
    return Emotion::kHappy;
  if (text == "angry")
    return Emotion::kAngry;
  if (text == "disturbed")
    return Emotion::kDisturbed;
  return std::nullopt;
}

const char* to_string(Gender gender) {
  switch (gender) {
    case Gender::kFemale:
      return "female";
    case Gender::kMale:
      return "male";
    case Gender::kNonIdentified:
      return "non-identified";
  }
  return "non-identified";
}

const char* to_string(Emotion emotion) {
  switch (emotion) {
    case Emotion::kNeutral:
      return "neutral";
    case Emotion::kHappy:
      return "happy";
    case Emotion::kAngry:
      return "angry";
    case Emotion::kDisturbed:
      return "disturbed";
  }
  return "neutral";
}

}  // namespace ari_social_sim::model
