#pragma once

#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/model/person_attributes.hpp"

namespace ari_social_sim::perception {

/// How an emotion of the world appears as an hri_msgs/Expression: one of its named expressions
/// and a point of the valence-arousal circumplex (both in [-1, 1]). The world's "disturbed" has
/// no namesake; it is reported as "scared" (negative valence, raised arousal): docs/perception.md.
struct ExpressionLabel {
  const char* name;
  double valence;
  double arousal;
};

ExpressionLabel expression_of(model::Emotion emotion);

}  // namespace ari_social_sim::perception
