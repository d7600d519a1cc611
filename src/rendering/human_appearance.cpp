#include "ari_social_sim/rendering/human_appearance.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::rendering {
namespace {

Eigen::Vector3f rgb(int r, int g, int b) {
  return Eigen::Vector3f(r, g, b) / 255.0f;
}

// Six skin tones from light to dark, each about a sixth of the people drawn: one colour in each
// of the six colorimetric skin classes by individual typology angle ITA = atan((L* - 50) / b*)
// (very light > 55 deg, light > 41, intermediate > 28, tan > 10, brown > -30, dark; Chardon et
// al. 1991, Del Bino et al. 2006), at ITA 60, 48, 34.5, 19, -10 and -40 deg with b* 15 to 18 (13
// for the darkest) and a* 8 to 12, converted from CIELAB (D65) to sRGB: L* from 76 down to 39.
// The colours before spanned L* 86 to 27, lighter and darker than skin measures.
const std::array<Eigen::Vector3f, 6> kSkinTones{{rgb(213, 181, 160), rgb(192, 159, 137),
                                                 rgb(177, 142, 119), rgb(164, 127, 104),
                                                 rgb(140, 103, 81), rgb(116, 85, 72)}};

const std::array<Eigen::Vector3f, 5> kHairColours{
    {rgb(28, 24, 22), rgb(62, 42, 30), rgb(104, 72, 46), rgb(186, 152, 100), rgb(132, 66, 38)}};
const Eigen::Vector3f kGreyHair = rgb(168, 166, 162);

const std::array<Eigen::Vector3f, 12> kTops{
    {rgb(48, 84, 170), rgb(180, 52, 52), rgb(52, 140, 72), rgb(214, 160, 40), rgb(120, 74, 156),
     rgb(46, 142, 150), rgb(236, 236, 230), rgb(40, 40, 44), rgb(128, 128, 132), rgb(204, 112, 150),
     rgb(150, 96, 60), rgb(92, 120, 60)}};
const std::array<Eigen::Vector3f, 6> kTrousers{{rgb(38, 52, 86), rgb(28, 28, 32), rgb(96, 96, 100),
                                                rgb(176, 158, 120), rgb(92, 64, 44),
                                                rgb(60, 90, 140)}};
const std::array<Eigen::Vector3f, 4> kShoes{
    {rgb(24, 20, 18), rgb(80, 50, 32), rgb(230, 230, 226), rgb(60, 60, 66)}};
const std::array<Eigen::Vector3f, 3> kMasks{
    {rgb(158, 200, 226), rgb(238, 238, 236), rgb(44, 44, 48)}};
const std::array<Eigen::Vector3f, 3> kIrises{{rgb(62, 40, 26), rgb(92, 112, 130), rgb(86, 96, 54)}};

template <class Palette>
const Eigen::Vector3f& pick(const Palette& palette, core::Rng& rng) {
  return palette[rng.uniform_index(palette.size())];
}

double mean_adult_height_m(model::Gender gender) {
  switch (gender) {
    case model::Gender::kMale:
      return 1.75;
    case model::Gender::kFemale:
      return 1.62;
    case model::Gender::kNonIdentified:
      break;
  }
  return 1.685;
}

// Mean stature at an age: Weech's rule (77 cm + 6 cm per year) from 2 to 12, linear to the adult
// mean at 18, a centimetre lost per decade after 60.
double mean_height_m(double age_years, model::Gender gender) {
  const double adult = mean_adult_height_m(gender);
  if (age_years < 2.0) {
    return 0.50 + 0.135 * age_years;
  }
  if (age_years < 12.0) {
    return 0.77 + 0.06 * age_years;
  }
  if (age_years < 18.0) {
    const double at_12 = 0.77 + 0.06 * 12.0;
    return at_12 + (adult - at_12) * (age_years - 12.0) / 6.0;
  }
  return adult - 0.001 * std::max(0.0, age_years - 60.0);
}

// Chin-to-crown height as a share of stature: 0.13 for adults, larger the younger.
double head_share(double age_years) {
  return 0.13 + 0.08 * std::clamp((16.0 - age_years) / 14.0, 0.0, 1.0);
}

}  // namespace

HumanAppearance appearance_of(const HumanTraits& traits, uint64_t seed) {
  core::Rng rng = core::rng_for(seed, core::rng_streams::kHumanAppearance, traits.id);
  HumanAppearance look;
  const double z = std::clamp(rng.normal(0.0, 1.0), -2.5, 2.5);
  const double mean = mean_height_m(traits.age_years, traits.gender);
  look.height_m = std::max(0.6, mean * (1.0 + z * 0.04));  // 0.07 m of 1.75 m
  look.head_height_m = head_share(traits.age_years) * look.height_m;
  look.build = std::clamp(rng.normal(1.0, 0.06), 0.88, 1.15);
  look.female_build = traits.gender == model::Gender::kFemale ||
                      (traits.gender == model::Gender::kNonIdentified && rng.bernoulli(0.5));
  const size_t tone = rng.uniform_index(kSkinTones.size());
  look.skin = kSkinTones[tone];
  look.skin_tone = static_cast<int>(tone) + 1;
  // Greying starts in the forties and is common after 60.
  const double grey_probability = std::clamp((traits.age_years - 40.0) / 35.0, 0.0, 0.9);
  look.hair = rng.bernoulli(grey_probability) ? kGreyHair : pick(kHairColours, rng);
  const bool bald = !look.female_build && traits.age_years > 35.0 && rng.bernoulli(0.2);
  const bool long_hair = rng.bernoulli(look.female_build ? 0.65 : 0.1);
  look.hair_style = bald ? HairStyle::kBald : (long_hair ? HairStyle::kLong : HairStyle::kShort);
  look.iris = pick(kIrises, rng);
  look.top = pick(kTops, rng);
  look.trousers = pick(kTrousers, rng);
  look.shoes = pick(kShoes, rng);
  look.short_sleeves = rng.bernoulli(0.35);
  look.mask = traits.mask;
  look.emotion = traits.emotion;
  look.mask_colour = pick(kMasks, rng);
  look.left_handed = rng.bernoulli(0.1);  // drawn last: the earlier draws keep their values
  return look;
}

}  // namespace ari_social_sim::rendering
