#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "ari_social_sim/model/person_attributes.hpp"

namespace ari_social_sim::rendering {

/// What the world says about a person that shapes how they look.
struct HumanTraits {
  uint32_t id{0};
  double age_years{35.0};
  model::Gender gender{model::Gender::kNonIdentified};
  bool mask{false};
  model::Emotion emotion{model::Emotion::kNeutral};

  bool operator==(const HumanTraits& other) const {
    return id == other.id && age_years == other.age_years && gender == other.gender &&
           mask == other.mask && emotion == other.emotion;
  }
  bool operator!=(const HumanTraits& other) const { return !(*this == other); }
};

enum class HairStyle { kShort, kLong, kBald };

/// How one person looks: stature and head size, and the colours of skin, hair, clothes and mask.
/// Colours are display RGB in [0, 1], as the renderer takes them.
struct HumanAppearance {
  double height_m{1.70};
  double head_height_m{0.22};  // chin to crown
  double build{1.0};           // width of shoulders and hips relative to the average build
  bool female_build{false};    // narrower shoulders, wider hips
  HairStyle hair_style{HairStyle::kShort};
  bool short_sleeves{false};
  bool mask{false};
  bool left_handed{false};                           // gestures most with the left hand
  model::Emotion emotion{model::Emotion::kNeutral};  // what the face's brows and mouth show
  Eigen::Vector3f skin{0.88f, 0.70f, 0.57f};
  int skin_tone{2};  // which of the six tones `skin` is: 1 the lightest, 6 the darkest
  Eigen::Vector3f hair{0.24f, 0.16f, 0.10f};  // the colour seen: pigmented and grey hairs mixed
  double hair_grey_share{0.0};                // the share of grey hairs, 0-1
  double hairline_recession{0.0};  // how far back the hairline has moved, in head heights
  Eigen::Vector3f iris{0.25f, 0.16f, 0.10f};
  Eigen::Vector3f top{0.2f, 0.35f, 0.75f};
  Eigen::Vector3f trousers{0.15f, 0.18f, 0.28f};
  Eigen::Vector3f shoes{0.1f, 0.08f, 0.07f};
  Eigen::Vector3f mask_colour{0.62f, 0.78f, 0.88f};
};

/// Draws a person's appearance from their traits and a seed; the same (traits, seed) always gives
/// the same look, and a person's look does not depend on who else is in the scene.
///   - Stature: adult means 1.75 m (men) and 1.62 m (women), standard deviation 0.07 m, as
///     in national surveys of European adults; children grow about 6 cm a year from 77 cm at
///     birth-to-two (Weech's rule) and reach the adult stature at 18; people over 60 lose about
///     1 cm per decade.
///   - Head: 0.13 of an adult's stature (chin to crown), up to 0.21 for a toddler.
///   - Skin: six tones from light to dark in about equal shares; hair colour darkening with skin
///     tone; grey hairs from middle age, later and fewer with darker skin (Panhard et al. 2012);
///     brown eyes for nearly all of the darker tones, light eyes mostly with the lightest
///     (Katsara and Nothnagel 2019); a hairline that recedes with age, further for men
///     (Hamilton 1951, Norwood 1975); clothes from everyday colours.
///   - Handedness: one in ten left-handed (Papadatou-Pastou et al. 2020: 10.6 %).
HumanAppearance appearance_of(const HumanTraits& traits, uint64_t seed);

}  // namespace ari_social_sim::rendering
