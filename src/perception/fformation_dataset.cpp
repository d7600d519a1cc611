#include "ari_social_sim/perception/fformation_dataset.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <utility>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/text_file.hpp"

namespace ari_social_sim::perception {
namespace {

std::string join(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) {
    joined += (joined.empty() ? "" : ",") + name;
  }
  return joined;
}

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// Line-by-line reader of one CSV file with a fixed header; every error names file:line:column.
// The datasets' tables are a few tens of kilobytes (CoffeeBreak, Synth); a table is held in memory
// whole, so a file past this is refused before it is read.
constexpr std::uintmax_t kMaxCsvFileBytes = 64 * 1024 * 1024;

class CsvReader {
 public:
  CsvReader(std::string path, std::vector<std::string> columns)
      : path_(std::move(path)), columns_(std::move(columns)) {
    core::check_text_file(path_, "a CSV file", kMaxCsvFileBytes);
    in_.open(path_);
    if (!in_) {
      throw core::ConfigError(path_ + ": cannot open the file");
    }
    if (!next_line()) {
      line_number_ = 1;
      fail_at(1, "expected the header \"" + join(columns_) + "\", got an empty file");
    }
    split();
    std::vector<std::string> header(fields_.size());
    for (size_t c = 0; c < fields_.size(); ++c) {
      header[c] = field(c);
    }
    if (header != columns_) {
      fail_at(1, "expected the header \"" + join(columns_) + "\", got \"" + line_ + "\"");
    }
  }

  /// Advances to the next non-blank data row; false at the end of the file.
  bool next_row() {
    do {
      if (!next_line()) {
        return false;
      }
    } while (std::all_of(line_.begin(), line_.end(), is_blank));
    split();
    if (fields_.size() < columns_.size()) {
      fail_at(line_.size() + 1, "expected " + std::to_string(columns_.size()) + " fields (" +
                                    join(columns_) + "), got " + std::to_string(fields_.size()));
    }
    if (fields_.size() > columns_.size()) {
      fail_at(fields_[columns_.size()].first + 1, "expected " + std::to_string(columns_.size()) +
                                                      " fields (" + join(columns_) + "), got " +
                                                      std::to_string(fields_.size()));
    }
    return true;
  }

  /// The non-empty text of `column`.
  std::string text(size_t column) const {
    std::string value = field(column);
    if (value.empty()) {
      fail_value(column, "expected a non-empty value", value);
    }
    return value;
  }

  FrameId integer(size_t column) const {
    const std::string value = field(column);
    errno = 0;
    char* end = nullptr;
    const long long parsed = std::strtoll(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || errno == ERANGE) {
      fail_value(column, "expected an integer", value);
    }
    return parsed;
  }

  double number(size_t column) const {
    const std::string value = field(column);
    char* end = nullptr;
    const double parsed = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(parsed)) {
      fail_value(column, "expected a finite number", value);
    }
    return parsed;
  }

  /// Throws `file:line:column: <column name>: <message>` about a field of the current row.
  [[noreturn]] void fail(size_t column, const std::string& message) const {
    fail_at(fields_[column].first + 1, columns_[column] + ": " + message);
  }

 private:
  [[noreturn]] void fail_value(size_t column, const std::string& expectation,
                               const std::string& value) const {
    fail(column, expectation + ", got \"" + value + "\"");
  }

  bool next_line() {
    if (!std::getline(in_, line_)) {
      return false;
    }
    ++line_number_;
    if (!line_.empty() && line_.back() == '\r') {
      line_.pop_back();
    }
    return true;
  }

  // Cuts line_ at commas into (start, length) pairs of the trimmed fields.
  void split() {
    fields_.clear();
    size_t start = 0;
    while (true) {
      size_t end = line_.find(',', start);
      if (end == std::string::npos) {
        end = line_.size();
      }
      size_t first = start;
      size_t last = end;
      while (first < last && is_blank(line_[first])) {
        ++first;
      }
      while (last > first && is_blank(line_[last - 1])) {
        --last;
      }
      fields_.emplace_back(first, last - first);
      if (end == line_.size()) {
        break;
      }
      start = end + 1;
    }
  }

  std::string field(size_t column) const {
    return line_.substr(fields_[column].first, fields_[column].second);
  }

  [[noreturn]] void fail_at(size_t character, const std::string& message) const {
    throw core::ConfigError(path_ + ":" + std::to_string(line_number_) + ":" +
                            std::to_string(character) + ": " + message);
  }

  std::string path_;
  std::vector<std::string> columns_;
  std::ifstream in_;
  std::string line_;
  size_t line_number_{0};
  std::vector<std::pair<size_t, size_t>> fields_;
};

}  // namespace

FeatureTable read_fformation_features(const std::string& path) {
  CsvReader reader(path, {"frame", "person_id", "x", "y", "theta"});
  FeatureTable table;
  std::set<std::pair<FrameId, std::string>> seen;
  while (reader.next_row()) {
    const FrameId frame = reader.integer(0);
    GcffPerson person{reader.text(1), reader.number(2), reader.number(3), reader.number(4)};
    if (!seen.emplace(frame, person.id).second) {
      reader.fail(1, "\"" + person.id + "\" appears twice in frame " + std::to_string(frame));
    }
    table[frame].push_back(std::move(person));
  }
  return table;
}

GroupTable read_fformation_groups(const std::string& path) {
  CsvReader reader(path, {"frame", "group", "person_id"});
  GroupTable table;
  // Per frame: the group labels in order of appearance, and the people already placed.
  std::map<FrameId, std::vector<std::string>> labels;
  std::set<std::pair<FrameId, std::string>> seen;
  while (reader.next_row()) {
    const FrameId frame = reader.integer(0);
    const std::string label = reader.text(1);
    std::string person = reader.text(2);
    if (!seen.emplace(frame, person).second) {
      reader.fail(2, "\"" + person + "\" is in two groups of frame " + std::to_string(frame));
    }
    std::vector<std::string>& frame_labels = labels[frame];
    Grouping& groups = table[frame];
    const size_t index =
        std::find(frame_labels.begin(), frame_labels.end(), label) - frame_labels.begin();
    if (index == frame_labels.size()) {
      frame_labels.push_back(label);
      groups.emplace_back();
    }
    groups[index].push_back(std::move(person));
  }
  return table;
}

std::vector<FrameId> read_fformation_frames(const std::string& path) {
  CsvReader reader(path, {"frame"});
  std::vector<FrameId> frames;
  std::set<FrameId> seen;
  while (reader.next_row()) {
    const FrameId frame = reader.integer(0);
    if (!seen.insert(frame).second) {
      reader.fail(0, "frame " + std::to_string(frame) + " is listed twice");
    }
    frames.push_back(frame);
  }
  return frames;
}

GroupTable detect_fformation_groups(const FeatureTable& features, const GcffParams& params,
                                    const std::function<bool()>& stop) {
  GcffDetector detector(params);
  GcffResult result;
  GroupTable table;
  for (const auto& [frame, persons] : features) {
    if (stop && stop()) {
      break;
    }
    detector.detect(persons, result);
    Grouping& groups = table[frame];
    for (const GcffGroup& group : result.groups) {
      std::vector<std::string>& ids = groups.emplace_back();
      for (const size_t member : group.members) {
        ids.push_back(persons[member].id);
      }
    }
  }
  return table;
}

}  // namespace ari_social_sim::perception
