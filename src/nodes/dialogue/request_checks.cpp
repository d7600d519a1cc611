#include "request_checks.hpp"

#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/dialogue/robot_action_request.hpp"

namespace ari_social_sim::nodes {

void check_tts_goal(const TtsGoal& goal) {
  if (goal.rawtext.text.empty() && !goal.text.key.empty()) {
    throw core::RequestError(
        "text: I18nText lookup (section/key) is not simulated; fill "
        "rawtext.text");
  }
  dialogue::check_spoken_text(goal.rawtext.text, "rawtext.text");
  if (!std::isfinite(goal.wait_before_speaking) || goal.wait_before_speaking < 0.0 ||
      goal.wait_before_speaking > kMaxWaitBeforeSpeakingS) {
    throw core::RequestError("wait_before_speaking: expected a number of seconds in [0, " +
                             core::number_text(kMaxWaitBeforeSpeakingS) + "], got " +
                             core::number_text(goal.wait_before_speaking));
  }
}

}  // namespace ari_social_sim::nodes
