#include "ari_social_sim/batch/episode_csv.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::batch {
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

// One CSV record: its fields unquoted, and where it ends (after its newline). A quoted field may
// hold commas, doubled quotes and newlines, as quoted() writes them.
struct CsvRecord {
  std::vector<std::string> fields;
  size_t end{0};
  bool complete{false};  // ended by a newline outside quotes
};

CsvRecord read_record(const std::string& text, size_t from) {
  CsvRecord record;
  std::string field;
  bool in_quotes = false;
  size_t i = from;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      in_quotes = true;
    } else if (c == ',') {
      record.fields.push_back(field);
      field.clear();
    } else if (c == '\n') {
      record.complete = true;
      ++i;
      break;
    } else {
      field += c;
    }
  }
  record.fields.push_back(field);
  record.end = i;
  return record;
}

bool read_unsigned(const std::string& text, uint64_t& value) {
  if (text.empty() || text.size() > 19 ||
      text.find_first_not_of("0123456789") != std::string::npos) {
    return false;
  }
  value = std::stoull(text);
  return true;
}

// `name=seconds;...` in order; a state that re-entered itself N times in a row as `name*N`, and
// the visits past the runner's record as one `(N more)`.
std::string states_field(const scenario::ScriptRunner& runner, double end_time_s) {
  const auto& visits = runner.visits();
  const double recorded_until_s =
      runner.unrecorded_visits() > 0 ? runner.unrecorded_from_s() : end_time_s;
  std::string field;
  for (size_t i = 0; i < visits.size(); ++i) {
    const double end_s = i + 1 < visits.size() ? visits[i + 1].enter_s : recorded_until_s;
    const std::string repeats =
        visits[i].entries > 1 ? "*" + std::to_string(visits[i].entries) : "";
    field += (i == 0 ? "" : ";") + visits[i].state + repeats + "=" +
             number(end_s - visits[i].enter_s, 2);
  }
  if (runner.unrecorded_visits() > 0) {
    field += ";(" + std::to_string(runner.unrecorded_visits()) +
             " more)=" + number(end_time_s - recorded_until_s, 2);
  }
  return field;
}

}  // namespace

EpisodeSummary EpisodeSummary::of(const std::string& scenario, uint64_t episode, uint64_t seed,
                                  const scenario::ScriptRunner& runner,
                                  const scenario::EpisodeMetrics& metrics) {
  EpisodeSummary summary;
  summary.scenario = scenario;
  summary.episode = episode;
  summary.seed = seed;
  summary.finished = runner.finished();
  if (runner.outcome()) {
    summary.outcome = *runner.outcome();
  }
  summary.states = states_field(runner, summary.outcome.end_time_s);
  summary.metrics = metrics;
  for (const scenario::TranscriptLine& line : runner.transcript().lines()) {
    ++summary.utterances;
    summary.ari_utterances += line.speaker.is_ari() ? 1 : 0;
  }
  return summary;
}

std::string csv_header() {
  return "scenario,episode,seed,success,reason,final_state,duration_s,states,"
         "ari_path_length_m,min_clearance_m,contacts,personal_space_time_s,navigation_time_s,"
         "navigation_goals,navigation_failures,utterances,ari_utterances,turn_transitions,"
         "overlap_share,listener_gaze_at_speaker,ari_floor_share,ari_interruptions,"
         "ari_addressed_after_s,ari_entered_in_pause";
}

EpisodeCsvRow EpisodeCsvRow::of(const EpisodeSummary& s) {
  return {s.scenario,
          s.episode,
          s.seed,
          s.finished && s.outcome.success,
          s.finished ? s.outcome.reason : "did not finish",
          s.outcome.final_state,
          /*text=*/""};
}

std::string csv_row(const EpisodeSummary& s) {
  const scenario::EpisodeMetrics& m = s.metrics;
  const world::ConversationFigures& talk = m.group_talk;
  const EpisodeCsvRow row = EpisodeCsvRow::of(s);
  return quoted(row.scenario) + "," + std::to_string(row.episode) + "," + std::to_string(row.seed) +
         "," + (row.success ? "1" : "0") + "," + quoted(row.reason) + "," +
         quoted(row.final_state) + "," + number(s.outcome.end_time_s) + "," + quoted(s.states) +
         "," + number(m.ari_path_length_m) + "," + number(m.min_clearance_m) + "," +
         std::to_string(m.contacts) + "," + number(m.personal_space_time_s) + "," +
         number(m.navigation_time_s) + "," + std::to_string(m.navigation_goals) + "," +
         std::to_string(m.navigation_failures) + "," + std::to_string(s.utterances) + "," +
         std::to_string(s.ari_utterances) + "," + std::to_string(talk.turn_transitions) + "," +
         number(talk.overlap_share) + "," + number(talk.listener_gaze_at_speaker) + "," +
         number(talk.ari_floor_share) + "," + std::to_string(talk.ari_interruptions) + "," +
         number(talk.ari_addressed_after_s) + "," + std::to_string(talk.ari_entered_in_pause);
}

EpisodeCsvContents read_episode_csv(const std::string& text, const std::string& source) {
  EpisodeCsvContents contents;
  const std::string header = csv_header() + "\n";
  if (text.size() < header.size() && header.compare(0, text.size(), text) == 0) {
    contents.partial_row = !text.empty();
    return contents;  // nothing, or the header cut short
  }
  if (text.compare(0, header.size(), header) != 0) {
    throw core::ConfigError(source + ":1: expected the header " + csv_header() +
                            " (the columns of this version), got another");
  }
  const size_t columns = read_record(header, 0).fields.size();
  contents.complete_bytes = header.size();
  std::set<uint64_t> episodes;
  size_t line = 2;
  for (size_t at = header.size(); at < text.size(); ++line) {
    const CsvRecord record = read_record(text, at);
    if (!record.complete) {
      contents.partial_row = true;
      break;
    }
    const std::string where = source + ":" + std::to_string(line) + ": ";
    EpisodeCsvRow row;
    if (record.fields.size() != columns) {
      throw core::ConfigError(where + "expected " + std::to_string(columns) + " columns, got " +
                              std::to_string(record.fields.size()));
    }
    row.scenario = record.fields[0];
    if (!read_unsigned(record.fields[1], row.episode) ||
        !read_unsigned(record.fields[2], row.seed)) {
      throw core::ConfigError(where + "expected an episode and a seed as integers, got '" +
                              record.fields[1] + "' and '" + record.fields[2] + "'");
    }
    if (record.fields[3] != "0" && record.fields[3] != "1") {
      throw core::ConfigError(where + "success: expected 0 or 1, got '" + record.fields[3] + "'");
    }
    row.success = record.fields[3] == "1";
    row.reason = record.fields[4];
    row.final_state = record.fields[5];
    if (!episodes.insert(row.episode).second) {
      throw core::ConfigError(where + "episode " + std::to_string(row.episode) +
                              " has a row already");
    }
    // A quoted field may span lines: count them all.
    for (size_t i = at; i + 1 < record.end; ++i) {
      line += text[i] == '\n' ? 1 : 0;
    }
    row.text = text.substr(at, record.end - at);
    contents.rows.push_back(row);
    contents.complete_bytes = record.end;
    at = record.end;
  }
  return contents;
}

}  // namespace ari_social_sim::batch
