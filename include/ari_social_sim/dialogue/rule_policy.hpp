#pragma once

#include <vector>

#include "ari_social_sim/dialogue/dialogue_env.hpp"
#include "ari_social_sim/dialogue/domain.hpp"

namespace ari_social_sim::dialogue {

/// The built-in rule-based robot policy, a reference for corpora and RL baselines. It answers the
/// last perceived utterance addressed to ARI: requests with the domain's answer (or cant-help()
/// when ARI does not know or cannot match the request), greetings with greet(); inform(ari(name));
/// offer-help(), thanks with thank(), bye with thank(); bye(), requests for repetition by
/// repeating, r-confirm with affirm(); anything else, or nothing addressed to ARI, with silence.
/// Deterministic; holds a reference to the domain.
class RulePolicy {
 public:
  explicit RulePolicy(const Domain& domain);

  void reset();
  RobotAction act(const Observation& observation);

 private:
  const Domain& domain_;
  bool greeted_{false};
  std::vector<DialogueAct> last_acts_;
};

}  // namespace ari_social_sim::dialogue
