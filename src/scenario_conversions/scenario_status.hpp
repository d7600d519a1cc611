#pragma once

#include <string>

#include "ari_social_sim/ScenarioStatus.h"
#include "ari_social_sim/scenario/script_runner.hpp"

namespace ari_social_sim::nodes {

/// /scenario/status of a run at sim time `stamp_s`.
ScenarioStatus to_msg(const std::string& scenario_name, const scenario::ScriptRunner& runner,
                      double stamp_s);

}  // namespace ari_social_sim::nodes
