#include "ari_social_sim/scenario/episode_csv.hpp"

#include <cmath>
#include <cstdio>

namespace ari_social_sim::scenario {
namespace {

std::string number(double value, int decimals = 3) {
  if (!std::isfinite(value)) {
    return "";  // e.g. no human ever near: an empty cell, not "inf"
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) {
    return text;
  }
  std::string out = "\"";
  for (char c : text) {
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return out + "\"";
}

}  // namespace

EpisodeSummary EpisodeSummary::of(const std::string& scenario, uint64_t episode, uint64_t seed,
                                  const ScriptRunner& runner, const EpisodeMetrics& metrics,
                                  double wall_time_s) {
  EpisodeSummary summary;
  summary.scenario = scenario;
  summary.episode = episode;
  summary.seed = seed;
  summary.finished = runner.finished();
  if (runner.outcome()) {
    summary.outcome = *runner.outcome();
  }
  const auto& visits = runner.visits();
  for (size_t i = 0; i < visits.size(); ++i) {
    const double end_s = i + 1 < visits.size() ? visits[i + 1].enter_s : summary.outcome.end_time_s;
    summary.states +=
        (i == 0 ? "" : ";") + visits[i].state + "=" + number(end_s - visits[i].enter_s, 2);
  }
  summary.metrics = metrics;
  for (const TranscriptLine& line : runner.transcript().lines()) {
    ++summary.utterances;
    summary.ari_utterances += line.speaker.is_ari() ? 1 : 0;
  }
  summary.wall_time_s = wall_time_s;
  return summary;
}

std::string csv_header() {
  return "scenario,episode,seed,success,reason,final_state,duration_s,states,"
         "ari_path_length_m,min_clearance_m,contacts,personal_space_time_s,navigation_time_s,"
         "navigation_goals,navigation_failures,utterances,ari_utterances,wall_time_s";
}

std::string csv_row(const EpisodeSummary& s) {
  const EpisodeMetrics& m = s.metrics;
  return quoted(s.scenario) + "," + std::to_string(s.episode) + "," + std::to_string(s.seed) + "," +
         (s.finished && s.outcome.success ? "1" : "0") + "," +
         quoted(s.finished ? s.outcome.reason : "did not finish") + "," +
         quoted(s.outcome.final_state) + "," + number(s.outcome.end_time_s) + "," +
         quoted(s.states) + "," + number(m.ari_path_length_m) + "," + number(m.min_clearance_m) +
         "," + std::to_string(m.contacts) + "," + number(m.personal_space_time_s) + "," +
         number(m.navigation_time_s) + "," + std::to_string(m.navigation_goals) + "," +
         std::to_string(m.navigation_failures) + "," + std::to_string(s.utterances) + "," +
         std::to_string(s.ari_utterances) + "," + number(s.wall_time_s, 4);
}

}  // namespace ari_social_sim::scenario
