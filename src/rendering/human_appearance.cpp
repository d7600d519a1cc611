#include "ari_social_sim/rendering/human_appearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
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

// Black, dark brown, brown, blond and red hair.
const std::array<Eigen::Vector3f, 5> kHairColours{
    {rgb(28, 24, 22), rgb(62, 42, 30), rgb(104, 72, 46), rgb(186, 152, 100), rgb(132, 66, 38)}};

// Percent of each hair colour (kHairColours' order) by skin tone, light to dark. Hair and skin
// darken together (both are eumelanin): black hair is the most common in the world, red hair
// (1-2 % of people) comes with fair skin, and blond hair is mostly northern European, with
// exceptions such as the 5-10 % of dark-skinned Solomon Islanders who are blond (Kenny et al.
// 2012). Averaged over the six tones: black 46 %, dark brown 30, brown 14, blond 7, red 2.
const std::array<std::array<double, 5>, 6> kHairByTone{{{5, 35, 30, 22, 8},
                                                        {10, 40, 30, 15, 5},
                                                        {40, 40, 14, 5, 1},
                                                        {60, 32, 7, 1, 0},
                                                        {75, 22, 3, 0, 0},
                                                        {85, 13, 1, 1, 0}}};
// Hair without pigment, a little yellowed: what a head of only grey hairs looks like.
const Eigen::Vector3f kWhiteHair = rgb(214, 211, 204);

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
// Percent of each iris colour (kIrises' order: brown, blue-grey, green-hazel) by skin tone, light
// to dark. Light irises are frequent only in European populations, most in the north, and brown
// eyes nearly universal elsewhere (Katsara and Nothnagel 2019); the shares by tone are ours, so
// that over the six tones brown is 73 % (70-79 % of the world), blue-grey 17, green-hazel 10.
const std::array<std::array<double, 3>, 6> kIrisByTone{
    {{25, 55, 20}, {45, 35, 20}, {80, 8, 12}, {92, 3, 5}, {99, 0, 1}, {100, 0, 0}}};

template <class Palette>
const Eigen::Vector3f& pick(const Palette& palette, core::Rng& rng) {
  return palette[rng.uniform_index(palette.size())];
}

// A colour of `palette` drawn with skin tone `tone` (1-6), in the shares its table gives the tone.
template <class Palette, class SharesByTone>
const Eigen::Vector3f& pick_by_tone(const Palette& palette, const SharesByTone& percent_by_tone,
                                    int tone, core::Rng& rng) {
  const auto& percent = percent_by_tone[tone - 1];
  return palette[rng.categorical({percent.begin(), percent.end()})];
}

// The share of grey hairs at an age, for someone whose greying starts at the `quantile` of their
// skin tone's onset ages. Panhard et al. 2012 (4,192 people): between 45 and 65, 74 % had grey
// hairs, 27 % of their hair on average; at 50, 6-23 % had half their hair grey, fewest among
// people of Asian and African descent, who grey later and less. Here greying starts at a mean
// age of 45 for the lightest tone to 51 for the darkest (logistic, standard deviation 10 years)
// and takes the whole head 30 years later: at 50, 13 % of the lightest tone and 5 % of the
// darkest are half grey; between 45 and 65, 72 % have grey hairs, 29 % of their hair.
double grey_share(double age_years, int tone, double quantile) {
  constexpr double kOnsetSpreadYears = 10.0 * 0.5513;  // logistic scale: sd * sqrt(3) / pi
  constexpr double kYearsToAllGrey = 30.0;
  const double mean_onset = 45.0 + 1.2 * (tone - 1);
  const double q = std::clamp(quantile, 1e-6, 1.0 - 1e-6);
  const double onset = mean_onset + kOnsetSpreadYears * std::log(q / (1.0 - q));
  return std::clamp((age_years - onset) / kYearsToAllGrey, 0.0, 1.0);
}

// How far the hairline has moved back from a young adult's, in head heights. Men's recedes at the
// temples and front with age, and balding grows more common (Hamilton 1951; Norwood 1975: about
// a third of men balding at 50); women's front hairline mostly stays. The amounts are ours: from
// 25 to 65, up to 0.04 of the head's height (about 9 mm) for men and 0.02 for women.
double hairline_recession(double age_years, bool female_build) {
  const double progress = std::clamp((age_years - 25.0) / 40.0, 0.0, 1.0);
  return (female_build ? 0.02 : 0.04) * progress;
}

// Pigmented and grey hairs side by side: their light adds up (linear light, display gamma 2.2).
Eigen::Vector3f greyed(const Eigen::Vector3f& pigmented, double grey) {
  const auto linear = [](const Eigen::Vector3f& c) { return c.array().pow(2.2f).matrix(); };
  const Eigen::Vector3f mixed = (1.0f - static_cast<float>(grey)) * linear(pigmented) +
                                static_cast<float>(grey) * linear(kWhiteHair);
  return mixed.array().pow(1.0f / 2.2f).matrix();
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
  look.hair_grey_share = grey_share(traits.age_years, look.skin_tone, rng.uniform());
  look.hairline_recession = hairline_recession(traits.age_years, look.female_build);
  look.hair =
      greyed(pick_by_tone(kHairColours, kHairByTone, look.skin_tone, rng), look.hair_grey_share);
  const bool bald = !look.female_build && traits.age_years > 35.0 && rng.bernoulli(0.2);
  const bool long_hair = rng.bernoulli(look.female_build ? 0.65 : 0.1);
  look.hair_style = bald ? HairStyle::kBald : (long_hair ? HairStyle::kLong : HairStyle::kShort);
  look.iris = pick_by_tone(kIrises, kIrisByTone, look.skin_tone, rng);
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
