#pragma once

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::model {

/// Kendon's F-formation arrangements (D6.4 §3.4, figure 3.3): people around a shared o-space,
/// two facing each other, two at a right angle, or shoulder to shoulder facing the same way.
enum class Arrangement : uint8_t { kCircle = 0, kVisAVis = 1, kLShape = 2, kSideBySide = 3 };

inline constexpr core::Choice<Arrangement> kArrangements[] = {
    {Arrangement::kCircle, "circle"},
    {Arrangement::kVisAVis, "vis-a-vis"},
    {Arrangement::kLShape, "l-shape"},
    {Arrangement::kSideBySide, "side-by-side"}};

inline const char* to_string(Arrangement arrangement) {
  return core::choice_name(arrangement, kArrangements);
}

}  // namespace ari_social_sim::model
