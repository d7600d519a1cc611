#pragma once

#include "ari_social_sim/core/bounds.hpp"

namespace ari_social_sim::scenario {

/// The longest time_limit a script may have (sim s): a day. Longer runs are split into episodes;
/// a longer limit is a typo (an extra digit) more often than a plan.
constexpr double kMaxScriptTimeLimitS = 86400.0;

/// time_limit's allowed range: > 0 and at most kMaxScriptTimeLimitS.
inline core::Bounds script_time_limit_bounds() {
  return {0.0, kMaxScriptTimeLimitS, true};
}

}  // namespace ari_social_sim::scenario
