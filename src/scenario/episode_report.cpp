#include "ari_social_sim/scenario/episode_report.hpp"

#include <cmath>

#include "ari_social_sim/core/format_text.hpp"

namespace ari_social_sim::scenario {
std::string format_report(const std::string& scenario_name, const ScriptRunner& runner,
                          const EpisodeMetrics& metrics) {
  std::string report = "scenario " + scenario_name + " (times from the script's start)\n";
  report += "transcript:\n";
  for (const TranscriptLine& line : runner.transcript().lines()) {
    report += core::format_text("  [%7.2f s] ", line.start_s - runner.start_time_s()) +
              line.speaker_name + " (" + line.act + "): " + line.text + "\n";
  }
  report += "states:";
  for (const StateVisit& visit : runner.visits()) {
    report +=
        " " + visit.state + core::format_text(" %.2f s", visit.enter_s) +
        (visit.entries > 1 ? " (re-entered " + std::to_string(visit.entries - 1) + "x)" : "") + ",";
  }
  if (runner.unrecorded_visits() > 0) {
    report += core::format_text(" and %zu more from %.2f s,", runner.unrecorded_visits(),
                                runner.unrecorded_from_s());
  }
  if (!runner.visits().empty()) {
    report.pop_back();
  }
  report += "\n";
  if (const auto& outcome = runner.outcome()) {
    const std::string where = outcome->final_state.empty()
                                  ? "before the script started"
                                  : core::format_text("after %.2f s", outcome->end_time_s) +
                                        " in state " + outcome->final_state;
    if (outcome->interrupted) {
      report += (outcome->final_state.empty()
                     ? "outcome: interrupted before the script started"
                     : "outcome: interrupted in state " + outcome->final_state +
                           core::format_text(" after %.2f s", outcome->end_time_s)) +
                " (" + outcome->reason + ")\n";
    } else {
      report += std::string("outcome: ") + (outcome->success ? "success " : "failure ") + where +
                (outcome->reason.empty() ? "" : ": " + outcome->reason) + "\n";
    }
  } else {
    report += "outcome: not finished\n";
  }
  if (!metrics.has_ari) {
    return report + "navigation: no ARI in the scene\n";
  }
  report += core::format_text("navigation: path %.2f m, ", metrics.ari_path_length_m) +
            (std::isfinite(metrics.min_clearance_m)
                 ? core::format_text("min clearance %.2f m, ", metrics.min_clearance_m)
                 : std::string("nobody around, ")) +
            std::to_string(metrics.contacts) + " contacts, " +
            core::format_text("%.2f s in personal space, ", metrics.personal_space_time_s) +
            std::to_string(metrics.navigation_goals) + " goals (" +
            std::to_string(metrics.navigation_failures) + " failed) " +
            core::format_text("active for %.2f s\n", metrics.navigation_time_s);
  return report;
}

}  // namespace ari_social_sim::scenario
