#include "ari_social_sim/perception/expression.hpp"

namespace ari_social_sim::perception {

ExpressionLabel expression_of(model::Emotion emotion) {
  switch (emotion) {
    case model::Emotion::kHappy:
      return {"happy", 0.8, 0.5};
    case model::Emotion::kAngry:
      return {"angry", -0.6, 0.8};
    case model::Emotion::kDisturbed:
      return {"scared", -0.6, 0.6};
    case model::Emotion::kNeutral:
    default:
      return {"neutral", 0.0, 0.0};
  }
}

}  // namespace ari_social_sim::perception
