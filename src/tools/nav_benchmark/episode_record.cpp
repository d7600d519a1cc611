#include "episode_record.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/output_file.hpp"

namespace ari_social_sim::tools::nav {
namespace {

// The progress file's escapes for a field that may hold anything: tabs separate fields and a
// newline ends the record.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    out += c == '\\' ? "\\\\" : c == '\t' ? "\\t" : c == '\n' ? "\\n" : std::string(1, c);
  }
  return out;
}

std::string unescaped(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (text[i] == '\\' && (next == '\\' || next == 't' || next == 'n')) {
      out += next == 't' ? '\t' : next == 'n' ? '\n' : '\\';
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

// Every number with the digits that read back to the same double: a resumed run's CSV and table
// come from the same values as an uninterrupted run's.
std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

std::string exact_list(const std::vector<double>& values) {
  std::string out;
  for (double value : values) {
    out += (out.empty() ? "" : " ") + exact(value);
  }
  return out;
}

// Reads record_line's fields in its order, each a number unless read as text.
class FieldReader {
 public:
  FieldReader(const std::string& line, std::string source) : source_(std::move(source)) {
    // Not getline: it drops an empty last field (an empty reason).
    for (size_t start = 0;;) {
      const size_t tab = line.find('\t', start);
      fields_.push_back(line.substr(start, tab - start));
      if (tab == std::string::npos) {
        break;
      }
      start = tab + 1;
    }
  }
  std::string text() { return at(next_++); }
  double number() {
    const std::string& field = at(next_++);
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (field.empty() || *end != '\0') {
      throw core::ConfigError(source_ + ": field " + std::to_string(next_) +
                              ": expected a number, got '" + field + "'");
    }
    return value;
  }
  int integer() { return static_cast<int>(number()); }
  std::vector<double> numbers() {
    std::vector<double> values;
    std::stringstream in(at(next_++));
    for (std::string item; in >> item;) {
      values.push_back(std::strtod(item.c_str(), nullptr));
    }
    return values;
  }

 private:
  const std::string& at(size_t i) const {
    if (i >= fields_.size()) {
      throw core::ConfigError(source_ + ": expected 23 tab-separated fields, got " +
                              std::to_string(fields_.size()));
    }
    return fields_[i];
  }

  std::string source_;
  std::vector<std::string> fields_;
  size_t next_{0};
};

}  // namespace

double percentile(std::vector<double> values, double q) {
  if (values.empty()) {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const size_t index = std::min(
      values.size() - 1, static_cast<size_t>(std::ceil(q * values.size())) - (q > 0 ? 1 : 0));
  return values[index];
}

// Throws core::Error naming the path when writing fails; the file then keeps what it held.
void write_csv(const std::string& path, const std::vector<EpisodeRecord>& records) {
  core::OutputFile file("--csv", path);
  std::ostream& out = file.stream();
  out << "type,episode,seed,controller,profile,success,outcome,time_to_goal_s,path_length_m,"
         "path_length_ratio,person_collisions,static_collisions,min_person_distance_m,"
         "personal_space_share,ospace_intrusions,final_position_error_m,"
         "final_heading_error_rad,gcff_includes_ari,mean_abs_jerk,solve_cpu_median_ms,solve_cpu_"
         "max_ms,"
         "solves,reason\n";
  for (const EpisodeRecord& r : records) {
    const double ratio = r.shortest_path_m > 0.0 ? r.score.path_length_m / r.shortest_path_m : 0.0;
    std::string reason = r.reason;
    std::replace(reason.begin(), reason.end(), '"', '\'');
    char line[1024];
    std::snprintf(line, sizeof(line),
                  "%s,%d,%llu,%s,%s,%d,%s,%.2f,%.3f,%.3f,%d,%d,%.3f,%.4f,%d,%.3f,%.3f,%d,%.3f,%.3f,"
                  "%.3f,%zu,\"%s\"\n",
                  r.type.c_str(), r.index, static_cast<unsigned long long>(r.seed),
                  r.controller.c_str(), r.profile.c_str(), r.success ? 1 : 0, r.outcome.c_str(),
                  r.time_to_goal_s, r.score.path_length_m, ratio, r.score.person_collisions,
                  r.score.static_collisions, r.score.min_person_distance_m,
                  r.score.personal_space_share, r.score.ospace_intrusions, r.final_position_error_m,
                  r.final_heading_error_rad, r.gcff_includes_ari, r.score.mean_abs_jerk,
                  1e3 * percentile(r.solve_times_s, 0.5), 1e3 * percentile(r.solve_times_s, 1.0),
                  r.solve_times_s.size(), reason.c_str());
    out << line;
  }
  file.commit();
}

// A record as one line of tab-separated fields, for the progress file.
std::string record_line(const EpisodeRecord& r) {
  const navigation::EpisodeScore& s = r.score;
  const std::vector<std::string> fields = {r.type,
                                           r.controller,
                                           r.profile,
                                           r.outcome,
                                           std::to_string(r.index),
                                           std::to_string(r.seed),
                                           r.success ? "1" : "0",
                                           exact(r.time_to_goal_s),
                                           exact(r.shortest_path_m),
                                           exact(s.duration_s),
                                           exact(s.path_length_m),
                                           std::to_string(s.person_collisions),
                                           std::to_string(s.static_collisions),
                                           exact(s.min_person_distance_m),
                                           exact(s.personal_space_share),
                                           std::to_string(s.ospace_intrusions),
                                           exact(s.mean_abs_jerk),
                                           exact(r.final_position_error_m),
                                           exact(r.final_heading_error_rad),
                                           std::to_string(r.gcff_includes_ari),
                                           exact_list(r.solve_times_s),
                                           exact_list(r.solve_wall_times_s),
                                           escaped(r.reason)};
  std::string line;
  for (const std::string& field : fields) {
    line += (line.empty() ? "" : "\t") + field;
  }
  return line;
}

EpisodeRecord parse_record(const std::string& line, const std::string& source) {
  FieldReader in(line, source);
  EpisodeRecord r;
  r.type = in.text();
  r.controller = in.text();
  r.profile = in.text();
  r.outcome = in.text();
  r.index = in.integer();
  r.seed = static_cast<uint64_t>(std::stoull(in.text()));
  r.success = in.integer() != 0;
  r.time_to_goal_s = in.number();
  r.shortest_path_m = in.number();
  r.score.duration_s = in.number();
  r.score.path_length_m = in.number();
  r.score.person_collisions = in.integer();
  r.score.static_collisions = in.integer();
  r.score.min_person_distance_m = in.number();
  r.score.personal_space_share = in.number();
  r.score.ospace_intrusions = in.integer();
  r.score.mean_abs_jerk = in.number();
  r.final_position_error_m = in.number();
  r.final_heading_error_rad = in.number();
  r.gcff_includes_ari = in.integer();
  r.solve_times_s = in.numbers();
  r.solve_wall_times_s = in.numbers();
  r.reason = unescaped(in.text());
  return r;
}

}  // namespace ari_social_sim::tools::nav
