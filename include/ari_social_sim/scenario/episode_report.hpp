#pragma once

#include <string>

#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"

namespace ari_social_sim::scenario {

/// What scenario_node and the batch tool print at the end of a run: the transcript, the states
/// visited, the outcome and the navigation figures, all times from the script's start, e.g.
///   transcript:
///     [  14.20 s] ARI (QUESTION:HELP): Hello, I am ARI. Can I help you?
///   states: grouping 0.00 s, ask_help 14.20 s, ...
///   outcome: success after 41.35 s in state leave: ARI left the group
///   navigation: path 9.12 m, min clearance 0.41 m, 0 contacts, ...
/// An interrupted run says so: `outcome: interrupted in state ask_help after 12.30 s (SIGINT)`;
/// a run that ended before its first tick: `outcome: failure before the script started: ...`.
std::string format_report(const std::string& scenario_name, const ScriptRunner& runner,
                          const EpisodeMetrics& metrics);

}  // namespace ari_social_sim::scenario
