#include "ari_social_sim/perception/expression.hpp"

namespace ari_social_sim::perception {

ExpressionLabel expression_of(world::Emotion emotion) {
  switch (emotion) {
    case world::Emotion::kHappy:
      return {"happy", 0.8, 0.5};
    case world::Emotion::kAngry:
      return {"angry", -0.6, 0.8};
    case world::Emotion::kDisturbed:
      return {"scared", -0.6, 0.6};
    case world::Emotion::kNeutral:
    default:
      return {"neutral", 0.0, 0.0};
  }
}

}  // namespace ari_social_sim::perception
